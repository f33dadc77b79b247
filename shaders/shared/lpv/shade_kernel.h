// shade's arithmetic: irradiance at a surface point from the accumulated volume
// [Martin 2012, §3.2.4; Kaplanyan & Dachsbacher 2010]: E = (1 / s^2) sum_i c_i(x) A_l Y_i(-n),
// with c trilinear between cell centres. The lobe is about -n (light flowing into the surface;
// Martin's Eq. 3.4 writes +n) and 1 / s^2 turns a cell's radiant intensity into radiance (Eq. 3.4
// omits it, so its result depends on the cell size): docs/lpv.md.
//
// Direct light from the analytic lights is shaded per pixel with the RSM depth as shadow map.
//
// Reads FETCH(accumulatedAt)(cell, word) -> float, 0 outside the grid; with lights also
// FETCH(lightAt)(i) -> LightData, FETCH(rsmViewAt)(i) -> RsmView and FETCH(rsmDepthAt)(view, texel)
// -> float, 0 where the texel saw nothing.
#ifndef VOXGI_LPV_SHADE_KERNEL_H
#define VOXGI_LPV_SHADE_KERNEL_H
#include "lpv_types.h"
#include "rsm_kernel.h"
#include "sh.h"

VOXGI_NAMESPACE_BEGIN

// Irradiance / pi at `position` (voxel-local) on a surface of unit normal `normal`, sampled
// p.offsetCells cells along the normal (shade.offset: away from the surface's own cell, whose light
// and blockers it shares).
VOLUME_FN vec3 lpvIrradiance(VOLUMES_IN vec3 position, vec3 normal, ShadeParams p) {
  int coefficients = p.coefficients;
  float lobe[9];
  for (int i = 0; i < coefficients; ++i) lobe[i] = shCosineLobe(i, -normal);
  // shade.offset cells along the normal, then cell centres at i + 1/2
  precise vec3 t = (position + normal * p.offsetCells) - vec3(0.5f);
  ivec3 base = ivec3(floor(t));
  precise vec3 f = t - vec3(base);
  precise vec3 sum = vec3(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 bit = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    precise float wx = bit.x == 1 ? f.x : 1.0f - f.x, wy = bit.y == 1 ? f.y : 1.0f - f.y,
                  wz = bit.z == 1 ? f.z : 1.0f - f.z;
    precise float weight = wx * wy * wz;
    if (weight == 0.0f) continue;
    ivec3 cell = base + bit;
    precise vec3 e = vec3(0.0f);
    for (int c = 0; c < 3; ++c) {
      precise float dotted = 0.0f;
      for (int i = 0; i < coefficients; ++i)
        dotted = dotted + FETCH(accumulatedAt)(cell, c * coefficients + i) * lobe[i];
      e[c] = dotted;
    }
    sum = sum + e * weight;
  }
  precise vec3 irradiance = sum * p.inverseCellArea;
  return irradiance * 0.318309886f;  // / pi
}

// Whether light `light` reaches p, a surface point whose normal is at cosine `cosine` to it: p's
// depth against the RSM's in the texel p falls in, of the light's view that p lies most squarely
// in front of (a cube face by p's major axis). The bias is rsm.bias texel footprints over the
// cosine, since a surface at angle theta spans footprint x tan(theta) of depth within one texel.
// A point outside every view (beside a spot's cone, outside a directional light's box) is lit.
VOLUME_FN float rsmVisibility(VOLUMES_IN RsmParams rp, int light, vec3 p, float cosine) {
  int resolution = rp.resolution;
  int best = -1;
  vec3 at = vec3(0.0f);
  float bestAxis = 0.0f;
  for (int i = 0; i < rp.viewCount; ++i) {
    RsmView v = FETCH(rsmViewAt)(i);
    if (v.light != light) continue;
    vec3 q = rsmProject(v, p);
    if (q.z <= 0.0f) continue;
    precise float axis = v.perspective == 1 ? q.z / length3(p - vec3(v.origin)) : 1.0f;
    if (best == -1 || axis > bestAxis) {
      best = i;
      bestAxis = axis;
      at = q;
    }
  }
  if (best == -1 || abs(at.x) > 1.0f || abs(at.y) > 1.0f) return 1.0f;
  RsmView v = FETCH(rsmViewAt)(best);
  precise float fx = (at.x + 1.0f) * 0.5f * float(resolution);
  precise float fy = (1.0f - at.y) * 0.5f * float(resolution);
  ivec2 texel = clamp(ivec2(int(floor(fx)), int(floor(fy))), ivec2(0), ivec2(resolution - 1));
  float depth = FETCH(rsmDepthAt)(best, texel);
  if (depth == 0.0f) return 1.0f;
  precise float footprint =
      2.0f * v.extent / float(resolution) * (v.perspective == 1 ? at.z : 1.0f);
  precise float bias = rp.biasTexels * footprint / max(cosine, 0.1f);
  return at.z <= depth + bias ? 1.0f : 0.0f;
}

// Direct light at p (normal n facing the camera) from the p.lightCount lights of the RSM (analytic
// lights and emissive triangles), as trace_cones computes it but with the shadow map's visibility
// instead of a shadow cone: diffuse gets the sum of E cos V / pi, specular the sum of E cos V
// times the Phong lobe about the mirror direction. A triangle's E cos is pi L F by Lambert's
// formula, its direction toward the part above the horizon, its shadow map the one from its
// centroid.
VOLUME_FN void lpvDirect(VOLUMES_IN vec3 position, vec3 normal, float shininess, ShadeParams p,
                         RsmParams rp, OUT(vec3) diffuse, OUT(vec3) specular) {
  diffuse = vec3(0.0f);
  specular = vec3(0.0f);
  precise vec3 view = normalize3(vec3(p.camera) - position);
  precise vec3 mirror = normal * (2.0f * dot3(normal, view)) - view;
  for (int i = 0; i < p.lightCount; ++i) {
    LightData l = FETCH(lightAt)(i);
    vec3 toLight;
    float distance;
    // The irradiance on a plane facing the light, and the surface's cosine to it; a triangle's
    // cosines are in its form factor already.
    vec3 e;
    float cosine, weight;
    if (l.kind == kLightTriangle) {
      float f = triangleFormFactor(l, position, normal, toLight, distance);
      e = vec3(l.intensity) * (kPi * f);
      cosine = dot3(normal, toLight);
      weight = 1.0f;
    } else {
      e = lightIrradiance(l, position, rp.voxelSize, toLight, distance);
      cosine = dot3(normal, toLight);
      weight = cosine;
    }
    if (e == vec3(0.0f)) continue;
    if (cosine <= 0.0f) continue;
    float visibility = l.castsShadows == 1u ? rsmVisibility(VOLUMES rp, i, position, cosine) : 1.0f;
    if (visibility == 0.0f) continue;
    precise vec3 arriving = e * (weight * visibility);
    diffuse = diffuse + arriving * kInvPi;
    specular = specular + arriving * phongLobe(dot3(mirror, toLight), shininess);
  }
}

VOXGI_NAMESPACE_END
#endif
