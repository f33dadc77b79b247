// One diffuse bounce per voxel ([Villegas 2017, "Voxel Global Illumination"], [Salm 2015, §4.4.3]),
// the cone library's gather: vct's bounce and svo's propagate run it on both backends (the CPU's
// lanes: cpu/cone/gather_lanes.h). The diffuse cone set from the voxel's
// centre over its normal hemisphere gathers E / pi from the pyramid of the previous bounce, which
// times the albedo is added to light_voxels' radiance. Reads FETCH(directAt|albedoAt|normalAt)
// besides the cone tracer's FETCH(pyramidAt|coneAt).
#ifndef VOXGI_CONE_GATHER_H
#define VOXGI_CONE_GATHER_H
#include "march.h"
#include "../vector_math.h"

VOXGI_NAMESPACE_BEGIN

// Where voxel v's diffuse cone sets start: `sides` sets (0: nothing to reflect the light, an empty
// voxel or a zero albedo; 1: around the normal n; 2: the two hemispheres about +z and -z, when
// the normals cancel) from the voxel's centre p. Split from gatherVoxel so that the CPU can march
// many voxels' cones together (cpu/cone/gather_lanes.h) and combine them as gatherVoxel does.
struct GatherSites {
  vec3 p;
  vec3 n;
  int sides;
};

VOLUME_FN GatherSites gatherSites(VOLUMES_IN ivec3 v) {
  GatherSites g;
  g.p = vec3(v) + vec3(0.5f);
  g.n = vec3(0.0f, 0.0f, 1.0f);
  g.sides = 0;
  vec4 direct = FETCH(directAt)(v);
  if (direct.a <= 0.0f) return g;
  vec3 albedo = FETCH(albedoAt)(v);
  if (albedo == vec3(0.0f)) return g;
  vec3 normalSum = FETCH(normalAt)(v);
  // Normals that cancel (the two sides of a thin wall) leave no hemisphere: the mean over the
  // sphere, as two hemispheres about z, as light_voxels lights such a voxel from every side.
  g.sides = normalSum == vec3(0.0f) ? 2 : 1;
  if (g.sides == 1) g.n = normalize3(normalSum);
  return g;
}

// The normal of set `side` (0 or 1).
VOXGI_FN vec3 gatherSideNormal(GatherSites g, int side) {
  return side == 0 ? g.n : -g.n;
}

// The origin of set `side`: the cone offset above the surface.
VOXGI_FN vec3 gatherSideOrigin(GatherSites g, int side, ConeTraceParams params) {
  precise vec3 origin = g.p + gatherSideNormal(g, side) * params.coneOffset;
  return origin;
}

// E / pi from the sets' radiance: the one set's, or the mean of the two.
VOXGI_FN vec3 gatheredLight(GatherSites g, vec3 first, vec3 second) {
  if (g.sides < 2) return first;
  precise vec3 mean = (first + second) * 0.5f;
  return mean;
}

// E / pi the diffuse cone set gathers at voxel v (0 for an empty voxel or a zero albedo: nothing
// to reflect it).
VOLUME_FN vec3 gatherVoxel(VOLUMES_IN ivec3 v, ConeTraceParams params) {
  GatherSites g = gatherSites(VOLUMES v);
  if (g.sides == 0) return vec3(0.0f);
  vec3 sets[2];
  sets[1] = vec3(0.0f);
  for (int side = 0; side < g.sides; ++side)
    sets[side] = gatherDiffuse(VOLUMES gatherSideOrigin(g, side, params), gatherSideNormal(g, side),
                               kMarchRadiance, params)
                     .radiance;
  return gatheredLight(g, sets[0], sets[1]);
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
