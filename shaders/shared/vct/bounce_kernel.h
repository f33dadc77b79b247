// One diffuse bounce per voxel ([Villegas 2017, "Voxel Global Illumination"], [Salm 2015, §4.4.3]),
// shared by cpu/vct/bounce.cpp and shaders/vct/bounce.comp: the diffuse cone set from the voxel's
// centre over its normal hemisphere gathers E / pi from the pyramid of the previous bounce, which
// times the albedo is added to light_voxels' radiance. Reads FETCH(directAt|albedoAt|normalAt)
// besides the cone tracer's FETCH(pyramidAt|coneAt).
#ifndef VOXGI_BOUNCE_KERNEL_H
#define VOXGI_BOUNCE_KERNEL_H
#include "cone_kernel.h"
#include "../vector_math.h"

VOXGI_NAMESPACE_BEGIN

// E / pi the diffuse cone set gathers at voxel v (0 for an empty voxel or a zero albedo: nothing
// to reflect it).
VOLUME_FN vec3 gatherVoxel(VOLUMES_IN ivec3 v, ConeTraceParams params) {
  vec4 direct = FETCH(directAt)(v);
  if (direct.a <= 0.0f) return vec3(0.0f);
  vec3 albedo = FETCH(albedoAt)(v);
  if (albedo == vec3(0.0f)) return vec3(0.0f);
  vec3 normalSum = FETCH(normalAt)(v);
  precise vec3 p = vec3(v) + vec3(0.5f);
  float offset = params.coneOffset;
  if (normalSum == vec3(0.0f)) {
    // Normals that cancel (the two sides of a thin wall) leave no hemisphere: the mean over the
    // sphere, as two hemispheres about z, as light_voxels lights such a voxel from every side.
    vec3 z = vec3(0.0f, 0.0f, 1.0f);
    precise vec3 above = p + z * offset;
    precise vec3 below = p - z * offset;
    vec3 up = gatherDiffuse(VOLUMES above, z, kMarchRadiance, params).radiance;
    vec3 down = gatherDiffuse(VOLUMES below, -z, kMarchRadiance, params).radiance;
    precise vec3 mean = (up + down) * 0.5f;
    return mean;
  }
  vec3 n = normalize3(normalSum);
  precise vec3 origin = p + n * offset;
  return gatherDiffuse(VOLUMES origin, n, kMarchRadiance, params).radiance;
}

// The direct radiance plus the albedo times `gathered`, premultiplied by direct.a.
VOXGI_FN vec4 addReflected(vec4 direct, vec3 albedo, vec3 gathered) {
  if (gathered == vec3(0.0f)) return direct;
  precise vec3 reflected = albedo * gathered * direct.a;
  precise vec3 rgb = vec3(direct) + reflected;
  return vec4(rgb, direct.a);
}

// Radiance leaving voxel v after one more bounce, premultiplied like light_voxels' (a: opacity).
VOLUME_FN vec4 bounceVoxel(VOLUMES_IN ivec3 v, ConeTraceParams params) {
  vec3 gathered = gatherVoxel(VOLUMES v, params);
  return addReflected(FETCH(directAt)(v), FETCH(albedoAt)(v), gathered);
}

VOXGI_NAMESPACE_END
#endif
