// Direct light per voxel ([Villegas 2017, §2]): outgoing diffuse radiance from every analytic
// light, attenuated by the plain cosine or Villegas' normal-weighted form, times the voxel's
// visibility toward the light found by marching the opacity volume (hard or soft, §2.2), plus
// emission (§2.3). Shared by cpu/vct/light_voxels.cpp and shaders/vct/light_voxels.comp. Volumes
// are read through FETCH(opacityAt|albedoAt|normalAt|emissionAt|lightAt) (glsl_cpp.h).
#ifndef VOXGI_LIGHT_VOXELS_KERNEL_H
#define VOXGI_LIGHT_VOXELS_KERNEL_H
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

// Visibility of the light from p: 1 unoccluded, 0 blocked. The ray starts `offset` voxels along
// the normal and marches in whole-voxel steps toward the light, reading the voxel it is in. At most
// ceil(sqrt(3) N) + 2 steps, so it always ends.
VOLUME_FN float voxelVisibility(VOLUMES_IN vec3 p, vec3 n, vec3 toLight, float distance,
                                LightVoxelsParams params) {
  int mode = params.voxelShadow;
  if (mode == kVoxelShadowNone) return 1.0f;
  int res = params.resolution;
  float offset = params.shadowOffset;
  precise vec3 origin = p + n * offset;
  int maxSteps = int(ceil(1.7320508f * float(res))) + 2;
  float occlusion = 0.0f;
  for (int i = 0; i < maxSteps; ++i) {
    float t = float(i);
    if (t >= distance - offset) break;
    precise vec3 q = origin + toLight * t;
    ivec3 v = ivec3(floor(q));
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= res || v.y >= res || v.z >= res) break;
    float a = FETCH(opacityAt)(v);
    if (a <= 0.0f) continue;
    if (mode == kVoxelShadowHard) {
      if (a >= 0.5f) return 0.0f;
    } else {
      // [Villegas 2017, §2.2.1]: nu += (1 - nu) kappa / t per collision, scaled by the voxel's
      // opacity.
      precise float hit = min(params.shadowKappa * a / (t + offset), 1.0f);
      precise float next = occlusion + (1.0f - occlusion) * hit;
      occlusion = next;
      if (occlusion >= 1.0f) return 0.0f;
    }
  }
  return 1.0f - occlusion;
}

// Radiance leaving voxel v, premultiplied by its opacity: rgb = opacity * (albedo/pi * sum of
// irradiance * attenuation * visibility + emission), a = opacity.
VOLUME_FN vec4 lightVoxel(VOLUMES_IN ivec3 v, LightVoxelsParams params) {
  float a = FETCH(opacityAt)(v);
  if (a <= 0.0f) return vec4(0.0f);
  vec3 albedo = FETCH(albedoAt)(v);
  vec3 n = normalize3(FETCH(normalAt)(v));
  precise vec3 p = vec3(v) + vec3(0.5f);
  precise vec3 irradiance = vec3(0.0f);
  for (int i = 0; i < params.lightCount; ++i) {
    LightData l = FETCH(lightAt)(i);
    vec3 toLight;
    float distance;
    if (l.kind == kLightTriangle) {
      // pi L F, F the form factor (cosine included). A voxel whose normals cancel faces the
      // triangle's centroid. The visibility ray stops 1.5 voxels short of the centroid, outside
      // the triangle's own voxels.
      precise vec3 middle =
          (vec3(l.position) + vec3(l.direction) + vec3(l.falloff)) * (1.0f / 3.0f);
      vec3 facing = n != vec3(0.0f) ? n : normalize3(middle - p);
      float f = triangleFormFactor(l, p, facing, toLight, distance);
      if (f <= 0.0f) continue;
      float seen = voxelVisibility(VOLUMES p, facing, toLight, max(distance - 1.5f, 0.0f), params);
      precise vec3 add = vec3(l.intensity) * (kPi * f * seen);
      irradiance = irradiance + add;
      continue;
    }
    vec3 e = lightIrradiance(l, p, params.voxelSize, toLight, distance);
    if (e == vec3(0.0f)) continue;
    // A voxel whose normals cancel has no preferred side: it takes the light unattenuated.
    float att = 1.0f;
    if (n != vec3(0.0f))
      att = params.normalWeighted == 1 ? normalWeightedAttenuation(n, toLight)
                                       : max(dot3(n, toLight), 0.0f);
    if (att <= 0.0f) continue;
    float vis =
        l.castsShadows == 1u ? voxelVisibility(VOLUMES p, n, toLight, distance, params) : 1.0f;
    precise vec3 add = e * (att * vis);
    irradiance = irradiance + add;
  }
  precise vec3 radiance = albedo * irradiance * kInvPi;
  if (params.emissive == 1) radiance = radiance + FETCH(emissionAt)(v);
  precise vec3 premultiplied = radiance * a;
  return vec4(premultiplied, a);
}

VOXGI_NAMESPACE_END
#endif
