// What a triangle adds to a voxel with its material's textures (docs/textures.md), for
// cpu/voxelize.cpp (common/voxel_walk.h) and shaders/voxelize.frag, voxelize_antialiased.comp: the
// albedo and emission are the textures' values where the triangle is sampled, filtered over one
// voxel's footprint; an untextured triangle adds its constants as before. Reads textures through
// FETCH (texture_kernel.h).
#ifndef VOXGI_VOXELIZE_SURFACE_H
#define VOXGI_VOXELIZE_SURFACE_H
#include "texture_kernel.h"
#include "voxelize_kernel.h"

VOXGI_NAMESPACE_BEGIN

VOXGI_FN bool voxelTextured(VoxelTriangle t) {
  return t.albedoTexture != kNoTexture || t.emissionTexture != kNoTexture;
}

// Texture coordinates at barycentric weights (b1, b2) of v1 and v2.
VOXGI_FN vec2 voxelTexcoord(VoxelTriangle t, vec2 b) {
  precise vec2 uv = (t.uv0 + b.x * (t.uv1 - t.uv0)) + b.y * (t.uv2 - t.uv0);
  return uv;
}

// Barycentric weights of v1 and v2 at point p of the triangle's plane, solved in its dominant
// plane (where its projection has the most area, so the 2 x 2 system is best conditioned).
VOXGI_FN vec2 voxelBarycentric(VoxelTriangle t, vec3 p) {
  precise vec3 a = toDominant(vec3(t.v0), t.dominantAxis);
  precise vec3 e1 = toDominant(vec3(t.v1), t.dominantAxis) - a;
  precise vec3 e2 = toDominant(vec3(t.v2), t.dominantAxis) - a;
  precise vec3 r = toDominant(p, t.dominantAxis) - a;
  precise float det = e1.x * e2.y - e2.x * e1.y;
  precise float b1 = (r.x * e2.y - e2.x * r.y) / det;
  precise float b2 = (e1.x * r.y - r.x * e1.y) / det;
  return vec2(b1, b2);
}

// The sums the triangle adds with `weight` where it is sampled at barycentric weights b.
VOLUME_FN VoxelContribution surfaceContribution(VOLUMES_IN VoxelTriangle t, uint weight, vec2 b) {
  if (!voxelTextured(t)) return weightedContribution(t, weight, t.albedo, t.emission);
  vec2 uv = voxelTexcoord(t, b);
  vec3 albedo = texturedValue(VOLUMES t.albedo, t.albedoTexture, uv, t.uvFootprint);
  vec3 emission = texturedValue(VOLUMES t.emission, t.emissionTexture, uv, t.uvFootprint);
  return weightedContribution(t, weight, albedo, emission);
}

// Conservative mode: does triangle t touch voxel `voxel`, and what does it add? Its part inside
// the voxel is sampled at the mean of that part's corners.
VOLUME_FN bool conservativeContribution(VOLUMES_IN VoxelTriangle t, ivec3 voxel,
                                        OUT(VoxelContribution) c) {
  uint weight;
  vec3 centre;
  if (!conservativeWeight(t, voxel, weight, centre)) return false;
  vec2 b = voxelTextured(t) ? voxelBarycentric(t, centre) : vec2(0.0f);
  c = surfaceContribution(VOLUMES t, weight, b);
  return true;
}

VOXGI_NAMESPACE_END
#endif
