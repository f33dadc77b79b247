// Trilinear filtering of a voxel level, shared by the dense pyramid's cone sampler
// (cone/march.h) and the sparse voxel octree's brick sampler (svo/svo_sample.h): one cell,
// one order of lerps, so both filter the same eight values to the same bits. Included by C++ and
// GLSL.
#ifndef VOXGI_TRILINEAR_H
#define VOXGI_TRILINEAR_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

VOXGI_FN vec4 lerp4(vec4 a, vec4 b, float t) {
  precise vec4 r = a + (b - a) * t;
  return r;
}

// The trilinear cell of `level` around p (level-0 voxel units): its lowest voxel, the weights
// toward the highest, and whether all 8 voxels lie inside a grid of `size` voxels per side.
struct TrilinearCell {
  ivec3 base;
  vec3 f;
  bool inside;
};

VOXGI_FN TrilinearCell trilinearCell(int level, vec3 p, int size) {
  TrilinearCell c;
  precise vec3 q = p * (1.0f / float(1 << level)) - vec3(0.5f);
  precise vec3 lowest = floor(q);
  precise vec3 f = q - lowest;
  c.f = f;
  c.base = ivec3(lowest);
  // Away from the border (nearly every tap) the 8 voxels skip their bounds tests.
  c.inside = c.base.x >= 0 && c.base.y >= 0 && c.base.z >= 0 && c.base.x + 1 < size &&
             c.base.y + 1 < size && c.base.z + 1 < size;
  return c;
}

// The eight voxels of a cell, c<x><y><z> the one at base + (x, y, z), blended with weights f.
VOXGI_FN vec4 blendCell(vec4 c000, vec4 c100, vec4 c010, vec4 c110, vec4 c001, vec4 c101, vec4 c011,
                        vec4 c111, vec3 f) {
  vec4 y0 = lerp4(lerp4(c000, c100, f.x), lerp4(c010, c110, f.x), f.y);
  vec4 y1 = lerp4(lerp4(c001, c101, f.x), lerp4(c011, c111, f.x), f.y);
  return lerp4(y0, y1, f.z);
}

VOXGI_NAMESPACE_END
#endif
