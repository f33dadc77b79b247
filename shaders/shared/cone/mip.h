// One voxel of a mip level from its 8 children (premultiplied RGBA), the cone library's mipmap:
// vct's mip and bounce build the dense pyramid with it, svo's mip and propagate the octree's node
// faces, on both backends. Children are read with FETCH(childAt)(face, child index) from the level
// below (the radiance volume for level 1, where `face` is ignored).
//
// Isotropic: the mean of the 8 children.
// Anisotropic ([Salm 2015, §4.4.2], [Villegas 2017, §3]): face f holds the voxel as seen by a cone
// travelling along f (+x, -x, +y, -y, +z, -z). Each of the 4 child pairs along f's axis is
// composited front to back — front = the child the cone reaches first (lower coordinate for a +
// face) — and the 4 results are averaged: c = front + (1 - front.a) * back.
#ifndef VOXGI_CONE_MIP_H
#define VOXGI_CONE_MIP_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

const int kFaces = 6;

VOLUME_FN vec4 mipIsotropic(VOLUMES_IN ivec3 v) {
  ivec3 b = v * 2;
  precise vec4 sum =
      ((FETCH(childAt)(0, b) + FETCH(childAt)(0, b + ivec3(1, 0, 0))) +
       (FETCH(childAt)(0, b + ivec3(0, 1, 0)) + FETCH(childAt)(0, b + ivec3(1, 1, 0)))) +
      ((FETCH(childAt)(0, b + ivec3(0, 0, 1)) + FETCH(childAt)(0, b + ivec3(1, 0, 1))) +
       (FETCH(childAt)(0, b + ivec3(0, 1, 1)) + FETCH(childAt)(0, b + ivec3(1, 1, 1))));
  precise vec4 mean = sum * 0.125f;
  return mean;
}

VOXGI_FN vec4 compositeFrontToBack(vec4 front, vec4 back) {
  precise vec4 r = front + back * (1.0f - front.a);
  return r;
}

VOLUME_FN vec4 mipAnisotropic(VOLUMES_IN ivec3 v, int face) {
  int axis = face / 2;
  bool positive = face % 2 == 0;
  ivec3 step = ivec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
  // The two axes across f, in a fixed order.
  ivec3 u = ivec3(axis == 0 ? 0 : 1, axis == 0 ? 1 : 0, 0);
  ivec3 w = ivec3(0, axis == 2 ? 1 : 0, axis == 2 ? 0 : 1);
  ivec3 b = v * 2;
  precise vec4 sum = vec4(0.0f);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec3 lo = b + u * i + w * j;
      vec4 near = FETCH(childAt)(face, positive ? lo : lo + step);
      vec4 far = FETCH(childAt)(face, positive ? lo + step : lo);
      sum = sum + compositeFrontToBack(near, far);
    }
  precise vec4 mean = sum * 0.25f;
  return mean;
}

VOXGI_NAMESPACE_END
#endif
