// Voxel cone tracing ([Villegas 2017, §4], [Kahl 2019, §4.3.2 and §5.4.4]), the cone library's
// march: every stage that traces cones runs it on both backends (the CPU's lanes:
// cpu/cone/cone_lanes.h). A cone marches from the surface, sampling the
// radiance pyramid at the level whose voxels match its diameter (quadrilinear: trilinear in two
// levels, blended), and composites premultiplied samples front to back. Volumes are read with
// FETCH(pyramidAt) (level 0: the radiance volume), FETCH(cellEmpty) and FETCH(coneAt).
#ifndef VOXGI_CONE_MARCH_H
#define VOXGI_CONE_MARCH_H
#include "../approx_math.h"
#include "../trilinear.h"
#include "cone_types.h"

VOXGI_NAMESPACE_BEGIN

// One march's result.
struct ConeHit {
  vec3 radiance;    // composited radiance, background included
  float occlusion;  // composited opacity
  float ambient;    // AO delta along this cone
};

VOXGI_FN ConeHit noConeHit() {
  ConeHit hit;
  hit.radiance = vec3(0.0f);
  hit.occlusion = 0.0f;
  hit.ambient = 0.0f;
  return hit;
}

const int kMarchRadiance = 0;
const int kMarchFirstHit = 1;  // [Kahl 2019, §5.4.4]: stop at the first sample with opacity > 1/100
const int kMarchShadow = 2;    // opacity only
const int kMarchShadowKahl = 3;  // opacity times smoothstep(0, max distance, sqrt(t) strength)

// Voxel v of `level` (0: the radiance volume) and `face` (directional pyramid); 0 outside the
// grid unless the caller already knows v is inside.
VOLUME_FN vec4 pyramidVoxel(VOLUMES_IN int level, int face, ivec3 v, int size, bool inside) {
  if (!inside && (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= size || v.y >= size || v.z >= size))
    return vec4(0.0f);
  return FETCH(pyramidAt)(level, face, v);
}

// Trilinear filter of one face of `level` over cell c, zero outside the grid.
VOLUME_FN vec4 filterCell(VOLUMES_IN int level, int face, TrilinearCell c, int size) {
#ifdef __cplusplus
  // A CPU accessor that stores whole cells (the octree's bricks, cpu/svo/svo_volumes.h) blends the
  // same eight values in the same order itself, one lookup instead of eight.
  if constexpr (requires(vec4 & cell) { volumes.filterBrickCell(level, face, c, cell); }) {
    vec4 fromBricks;
    if (volumes.filterBrickCell(level, face, c, fromBricks)) return fromBricks;
  }
#endif
#ifdef VOXGI_BRICK_CELLS
  // A GLSL includer that stores whole cells defines filterBrickCell (the octree's gather,
  // shaders/svo/propagate_gather.comp): the same eight values in the same order.
  return filterBrickCell(level, face, c);
#else
  ivec3 i = c.base;
  vec3 f = c.f;
  bool inside = c.inside;
  vec4 c000 = pyramidVoxel(VOLUMES level, face, i, size, inside);
  vec4 c100 = pyramidVoxel(VOLUMES level, face, i + ivec3(1, 0, 0), size, inside);
  vec4 c010 = pyramidVoxel(VOLUMES level, face, i + ivec3(0, 1, 0), size, inside);
  vec4 c110 = pyramidVoxel(VOLUMES level, face, i + ivec3(1, 1, 0), size, inside);
  vec4 c001 = pyramidVoxel(VOLUMES level, face, i + ivec3(0, 0, 1), size, inside);
  vec4 c101 = pyramidVoxel(VOLUMES level, face, i + ivec3(1, 0, 1), size, inside);
  vec4 c011 = pyramidVoxel(VOLUMES level, face, i + ivec3(0, 1, 1), size, inside);
  vec4 c111 = pyramidVoxel(VOLUMES level, face, i + ivec3(1, 1, 1), size, inside);
  return blendCell(c000, c100, c010, c110, c001, c101, c011, c111, f);
#endif
}

// One level as seen by a cone travelling along `dir`: the isotropic level, or the three faces of
// the directional pyramid that face the cone weighted by dir^2 (docs/stages/vct/mip.md). Level 0 is
// the isotropic radiance volume in both modes. A cell whose 8 voxels are all +0 filters to
// exactly +0, so FETCH(cellEmpty) may skip it.
VOLUME_FN vec4 sampleLevel(VOLUMES_IN int level, vec3 p, vec3 dir, ConeTraceParams params) {
  int size = params.resolution >> level;
  TrilinearCell c = trilinearCell(level, p, size);
  if (FETCH(cellEmpty)(level, c.base)) return vec4(0.0f);
  if (level == 0 || params.directional == 0) return filterCell(VOLUMES level, 0, c, size);
  precise vec3 w = dir * dir;
  precise vec4 sum = vec4(0.0f);
  if (w.x > 0.0f) sum = sum + filterCell(VOLUMES level, dir.x >= 0.0f ? 0 : 1, c, size) * w.x;
  if (w.y > 0.0f) sum = sum + filterCell(VOLUMES level, dir.y >= 0.0f ? 2 : 3, c, size) * w.y;
  if (w.z > 0.0f) sum = sum + filterCell(VOLUMES level, dir.z >= 0.0f ? 4 : 5, c, size) * w.z;
  return sum;
}

// Quadrilinear sample for a cone of `diameter` voxels (>= 1): level log2(diameter), clamped to
// the top of the pyramid.
VOLUME_FN vec4 sampleCone(VOLUMES_IN vec3 p, float diameter, vec3 dir, ConeTraceParams params) {
  precise float level = min(log2Approx(diameter), float(params.topLevel));
  precise float l0 = floor(level);
  precise float f = level - l0;
  vec4 a = sampleLevel(VOLUMES int(l0), p, dir, params);
  if (f == 0.0f) return a;
  vec4 b = sampleLevel(VOLUMES int(l0) + 1, p, dir, params);
  return lerp4(a, b, f);
}

VOXGI_FN float smoothstep01(float x) {
  precise float c = clamp(x, 0.0f, 1.0f);
  precise float r = c * c * (3.0f - 2.0f * c);
  return r;
}

// Marches one cone from `origin`, params.coneOffset voxels above the surface it leaves, along unit
// `dir`, which rises from that surface at `rise` (dir . n) voxels per voxel. Samples lie at
// t = 1/2, then t += max(beta d, min step) with d = max(2 t tan(aperture/2), 1) voxels; with
// cones.clearance c > 0 (params.coneClearance), d is at most c times the height above the surface,
// coneOffset + t rise, so that a wide cone's coarse samples do not hold the voxels of the surface
// it leaves (docs/stages/vct/trace_cones.md, "Self-occlusion"). Each sample's opacity a is
// corrected to the step, 1 - (1 - a)^beta. Stops when t passes `maxDistance`, the opacity reaches
// 0.999, or after params.maxSteps steps (enough to leave the grid); a cone that leaves the grid
// adds the background times its remaining transparency.
VOLUME_FN ConeHit marchCone(VOLUMES_IN vec3 origin, vec3 dir, float rise, float tanHalf,
                            float maxDistance, int kind, ConeTraceParams params) {
  ConeHit hit = noConeHit();
  float n = float(params.resolution);
  float beta = params.coneStep;
  bool ambient = params.ambientOcclusion == 1 && kind <= kMarchFirstHit;
  bool exited = false;
  precise float t = 0.5f;
  for (int i = 0; i < params.maxSteps; ++i) {
    if (t > maxDistance) break;
    precise vec3 q = origin + dir * t;
    if (q.x < 0.0f || q.y < 0.0f || q.z < 0.0f || q.x > n || q.y > n || q.z > n) {
      exited = true;
      break;
    }
    precise float width = 2.0f * t * tanHalf;
    if (params.coneClearance > 0.0f) {
      precise float height = params.coneOffset + t * rise;
      width = min(width, height * params.coneClearance);
    }
    precise float diameter = max(width, 1.0f);
    vec4 s = sampleCone(VOLUMES q, diameter, dir, params);
    float a = min(s.a, 1.0f);
    if (a > 0.0f) {
      // Kahl's shadow falloff replaces the step correction ([Kahl 2019, §5.4.4]).
      precise float corrected =
          kind == kMarchShadowKahl ? a * smoothstep01(sqrt(t) * params.shadowStrength / maxDistance)
          : beta == 1.0f || a >= 1.0f ? a
                                      : 1.0f - powApprox(1.0f - a, beta);
      if (kind == kMarchFirstHit && corrected > 0.01f) {
        precise vec3 surface = vec3(s) / s.a;
        hit.radiance = surface;
        hit.occlusion = 1.0f;
        return hit;
      }
      precise float remaining = 1.0f - hit.occlusion;
      if (kind <= kMarchFirstHit) {
        precise vec3 add = vec3(s) * (remaining * corrected / a);
        hit.radiance = hit.radiance + add;
      }
      if (ambient) {
        precise float falloff = 1.0f / (1.0f + params.ambientLambda * (0.5f * diameter));
        precise float delta = hit.ambient + (1.0f - hit.ambient) * corrected * falloff;
        hit.ambient = delta;
      }
      precise float next = hit.occlusion + remaining * corrected;
      hit.occlusion = next;
      if (hit.occlusion >= 0.999f) return hit;
    }
    t = t + max(beta * diameter, params.minStep);
  }
  if (exited && kind <= kMarchFirstHit) {
    precise vec3 sky = vec3(params.background) * (1.0f - hit.occlusion);
    hit.radiance = hit.radiance + sky;
  }
  return hit;
}

// A unit tangent frame around unit n (Duff et al. 2017), the sign taken with a comparison so both
// backends agree at n.z = -0.
VOXGI_FN void tangentFrame(vec3 n, OUT(vec3) t, OUT(vec3) b) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  precise float a = -1.0f / (s + n.z);
  precise float c = n.x * n.y * a;
  t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// The diffuse cones' hits so far, weighted.
struct DiffuseSum {
  vec3 radiance;  // E / pi when the weights sum to 1
  float ambient;  // the weighted ambient-occlusion delta
  float weights;
};

VOXGI_FN DiffuseSum noDiffuse() {
  DiffuseSum s;
  s.radiance = vec3(0.0f);
  s.ambient = 0.0f;
  s.weights = 0.0f;
  return s;
}

// Diffuse cone c's axis in the tangent frame (t, b, n).
VOXGI_FN vec3 diffuseConeDirection(vec3 t, vec3 b, vec3 n, ConeData c) {
  precise vec3 d = (t * c.direction.x + b * c.direction.y) + n * c.direction.z;
  return d;
}

VOXGI_FN DiffuseSum addDiffuseCone(DiffuseSum s, ConeHit h, ConeData c) {
  precise vec3 radiance = s.radiance + h.radiance * c.weight;
  precise float ambient = s.ambient + h.ambient * c.weight;
  precise float weights = s.weights + c.weight;
  s.radiance = radiance;
  s.ambient = ambient;
  s.weights = weights;
  return s;
}

VOXGI_FN float diffuseAmbientOcclusion(DiffuseSum s) {
  return s.weights > 0.0f ? s.ambient / s.weights : 0.0f;
}

// The diffuse cone set (FETCH(coneAt), params.diffuseConeCount cones in the tangent frame) around
// unit n from `origin`. Each cone rises from the surface at its direction's component along n.
VOLUME_FN DiffuseSum gatherDiffuse(VOLUMES_IN vec3 origin, vec3 n, int kind,
                                   ConeTraceParams params) {
  vec3 t;
  vec3 b;
  tangentFrame(n, t, b);
  DiffuseSum s = noDiffuse();
  for (int k = 0; k < params.diffuseConeCount; ++k) {
    ConeData c = FETCH(coneAt)(k);
    ConeHit h = marchCone(VOLUMES origin, diffuseConeDirection(t, b, n, c), c.direction.z,
                          c.tanHalfAperture, params.maxDistance, kind, params);
    s = addDiffuseCone(s, h, c);
  }
  return s;
}

VOXGI_NAMESPACE_END
#endif
