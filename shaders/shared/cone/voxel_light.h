// Direct light per voxel ([Villegas 2017, §2]): outgoing diffuse radiance from every analytic
// light, attenuated by the plain cosine or Villegas' normal-weighted form, times the voxel's
// visibility toward the light found by marching the opacity volume (hard or soft, §2.2), plus
// emission (§2.3). The cone library's voxel light: vct's light_voxels and svo's propagate run it on
// both backends (the CPU's lanes: cpu/cone/voxel_light_lanes.h). Volumes
// are read through FETCH(opacityAt|albedoAt|normalAt|emissionAt|lightAt) (glsl_cpp.h).
#ifndef VOXGI_CONE_VOXEL_LIGHT_H
#define VOXGI_CONE_VOXEL_LIGHT_H
#include "../area_light.h"

VOXGI_NAMESPACE_BEGIN

// std430-compatible, uploaded in front of the lights.
struct LightVoxelsParams {
  int resolution;      // N voxels per axis
  int lightCount;      // analytic lights (FETCH(lightAt))
  int normalWeighted;  // 1: light.attenuation=normal_weighted
  int voxelShadow;     // kVoxelShadow* (voxel_shadow.mode)
  float voxelSize;     // world units per voxel, for the lights' falloff
  float shadowKappa;   // the soft shadow's kappa (voxel_shadow.kappa)
  float shadowOffset;  // voxels along the normal a shadow ray starts (voxel_shadow.offset)
  int emissive;        // 1: the voxels' own emission is added
};

const int kVoxelShadowNone = 0;
const int kVoxelShadowHard = 1;
const int kVoxelShadowSoft = 2;

// Where the visibility ray from voxel centre p leaves: `offset` voxels along n.
VOXGI_FN vec3 shadowRayOrigin(vec3 p, vec3 n, LightVoxelsParams params) {
  precise vec3 origin = p + n * params.shadowOffset;
  return origin;
}

// The most whole-voxel steps a visibility ray takes in a grid of `res` voxels a side.
VOXGI_FN int shadowRayMaxSteps(int res) {
  return int(ceil(1.7320508f * float(res))) + 2;
}

// A visibility ray's occlusion after step t meets a voxel of opacity a > 0; the light is blocked
// once it reaches 1.
VOXGI_FN float shadowCollision(float occlusion, float a, float t, LightVoxelsParams params) {
  if (params.voxelShadow == kVoxelShadowHard) return a >= 0.5f ? 1.0f : occlusion;
  // [Villegas 2017, §2.2.1]: nu += (1 - nu) kappa / t per collision, scaled by the voxel's
  // opacity.
  precise float hit = min(params.shadowKappa * a / (t + params.shadowOffset), 1.0f);
  precise float next = occlusion + (1.0f - occlusion) * hit;
  return next;
}

// Visibility of the light from p: 1 unoccluded, 0 blocked. The ray starts `offset` voxels along
// the normal and marches in whole-voxel steps toward the light, reading the voxel it is in. At most
// shadowRayMaxSteps, so it always ends. (cpu/cone/shadow_lanes.h marches many at once, the same.)
VOLUME_FN float voxelVisibility(VOLUMES_IN vec3 p, vec3 n, vec3 toLight, float distance,
                                LightVoxelsParams params) {
  if (params.voxelShadow == kVoxelShadowNone) return 1.0f;
  int res = params.resolution;
  float offset = params.shadowOffset;
  vec3 origin = shadowRayOrigin(p, n, params);
  int maxSteps = shadowRayMaxSteps(res);
  float occlusion = 0.0f;
  for (int i = 0; i < maxSteps; ++i) {
    float t = float(i);
    if (t >= distance - offset) break;
    precise vec3 q = origin + toLight * t;
    ivec3 v = ivec3(floor(q));
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= res || v.y >= res || v.z >= res) break;
    float a = FETCH(opacityAt)(v);
    if (a <= 0.0f) continue;
    occlusion = shadowCollision(occlusion, a, t, params);
    if (occlusion >= 1.0f) return 0.0f;
  }
  return 1.0f - occlusion;
}

// One light's share of a voxel's irradiance before visibility, and the shadow ray that decides
// its visibility.
struct LightTerm {
  vec3 colour;      // the share is colour * (scale * visibility), scale lightTerm's result
  vec3 rayNormal;   // the ray leaves the voxel centre this far along it (voxel_shadow.offset)...
  vec3 toLight;     // ...and marches toward the light
  float rayLength;  // voxels from the centre to where the march stops
  bool shadowed;    // whether the light's visibility is marched at all
};

// Light l at voxel centre p (unit mean normal n, or 0 where the voxel's normals cancel): its term
// and scale, <= 0 where it adds nothing.
VOXGI_FN float lightTerm(LightData l, vec3 p, vec3 n, LightVoxelsParams params,
                         OUT(LightTerm) term) {
  float distance;
  if (l.kind == kLightTriangle) {
    // pi L F, F the form factor (cosine included). A voxel whose normals cancel faces the
    // triangle's centroid. The visibility ray stops 1.5 voxels short of the centroid, outside
    // the triangle's own voxels.
    precise vec3 middle = (vec3(l.position) + vec3(l.direction) + vec3(l.falloff)) * (1.0f / 3.0f);
    vec3 facing = n != vec3(0.0f) ? n : normalize3(middle - p);
    float f = triangleFormFactor(l, p, facing, term.toLight, distance);
    term.colour = vec3(l.intensity);
    term.rayNormal = facing;
    term.rayLength = max(distance - 1.5f, 0.0f);
    term.shadowed = true;
    return f > 0.0f ? kPi * f : 0.0f;
  }
  term.colour = lightIrradiance(l, p, params.voxelSize, term.toLight, distance);
  term.rayNormal = n;
  term.rayLength = distance;
  term.shadowed = l.castsShadows == 1u;
  if (term.colour == vec3(0.0f)) return 0.0f;
  // A voxel whose normals cancel has no preferred side: it takes the light unattenuated.
  if (n == vec3(0.0f)) return 1.0f;
  return params.normalWeighted == 1 ? normalWeightedAttenuation(n, term.toLight)
                                    : max(dot3(n, term.toLight), 0.0f);
}

// irradiance plus one light's share at the visibility found for it.
VOXGI_FN vec3 addLightShare(vec3 irradiance, LightTerm t, float scale, float visibility) {
  precise vec3 add = t.colour * (scale * visibility);
  precise vec3 sum = irradiance + add;
  return sum;
}

// Radiance leaving voxel v of opacity a > 0, premultiplied by it: rgb = a * (albedo/pi *
// irradiance + emission), alpha = a.
VOLUME_FN vec4 voxelRadiance(VOLUMES_IN ivec3 v, float a, vec3 albedo, vec3 irradiance,
                             LightVoxelsParams params) {
  precise vec3 radiance = albedo * irradiance * kInvPi;
  if (params.emissive == 1) radiance = radiance + FETCH(emissionAt)(v);
  precise vec3 premultiplied = radiance * a;
  return vec4(premultiplied, a);
}

// Radiance leaving voxel v, premultiplied by its opacity: rgb = opacity * (albedo/pi * sum of
// irradiance * attenuation * visibility + emission), a = opacity. (cpu/cone/voxel_light_lanes.h
// lights many voxels at once, the same.)
VOLUME_FN vec4 lightVoxel(VOLUMES_IN ivec3 v, LightVoxelsParams params) {
  float a = FETCH(opacityAt)(v);
  if (a <= 0.0f) return vec4(0.0f);
  vec3 albedo = FETCH(albedoAt)(v);
  vec3 n = normalize3(FETCH(normalAt)(v));
  precise vec3 p = vec3(v) + vec3(0.5f);
  vec3 irradiance = vec3(0.0f);
  for (int i = 0; i < params.lightCount; ++i) {
    LightTerm t;
    float scale = lightTerm(FETCH(lightAt)(i), p, n, params, t);
    if (scale <= 0.0f) continue;
    float vis =
        t.shadowed ? voxelVisibility(VOLUMES p, t.rayNormal, t.toLight, t.rayLength, params) : 1.0f;
    irradiance = addLightShare(irradiance, t, scale, vis);
  }
  return voxelRadiance(VOLUMES v, a, albedo, irradiance, params);
}

// A sequence's frame whose geometry moved and whose lights did not (docs/motion.md): voxelize's
// buffers differ from the frame before's only inside the box [changedLow, changedHigh] (voxel
// coordinates, a voxel's margin included), so a voxel outside it whose shadow rays all miss it
// lights as it did then. std430, the vct light_voxels shader's second block.
struct LightVoxelsUpdate {
  vec3 changedLow;
  int partial;  // 1: voxels that lightVoxelMayChange says not keep the frame before's radiance
  vec3 changedHigh;
  int padding;
};

// Whether the segment from o along unit d for `length` meets the box [low, high] (slabs).
VOXGI_FN bool segmentMeetsBox(vec3 o, vec3 d, float length, vec3 low, vec3 high) {
  float enter = 0.0f;
  float leave = length;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0f) {
      if (o[axis] < low[axis] || o[axis] > high[axis]) return false;
      continue;
    }
    float t0 = (low[axis] - o[axis]) / d[axis];
    float t1 = (high[axis] - o[axis]) / d[axis];
    enter = max(enter, min(t0, t1));
    leave = min(leave, max(t0, t1));
  }
  return enter <= leave;
}

// Whether voxel v's radiance can differ from the frame before's under `update`: v lies in the
// changed box, or a shadow ray it marches (voxelVisibility's: from the offset origin, at most
// its step count) meets the box. A voxel that lightVoxel leaves dark stays dark.
VOLUME_FN bool lightVoxelMayChange(VOLUMES_IN ivec3 v, LightVoxelsParams params,
                                   LightVoxelsUpdate update) {
  precise vec3 p = vec3(v) + vec3(0.5f);
  if (all(greaterThanEqual(p, update.changedLow)) && all(lessThanEqual(p, update.changedHigh)))
    return true;
  if (FETCH(opacityAt)(v) <= 0.0f || params.voxelShadow == kVoxelShadowNone) return false;
  vec3 n = normalize3(FETCH(normalAt)(v));
  float maxSteps = float(shadowRayMaxSteps(params.resolution));
  for (int i = 0; i < params.lightCount; ++i) {
    LightTerm t;
    float scale = lightTerm(FETCH(lightAt)(i), p, n, params, t);
    if (scale <= 0.0f || !t.shadowed) continue;
    float length = min(t.rayLength - params.shadowOffset, maxSteps);
    if (length < 0.0f) continue;
    if (segmentMeetsBox(shadowRayOrigin(p, t.rayNormal, params), t.toLight, length,
                        update.changedLow, update.changedHigh))
      return true;
  }
  return false;
}

VOXGI_NAMESPACE_END
#endif
