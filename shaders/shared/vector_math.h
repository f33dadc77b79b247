// Vector arithmetic written out so that C++ and GLSL evaluate it in the same order (glsl_cpp.h).
#ifndef VOXGI_VECTOR_MATH_H
#define VOXGI_VECTOR_MATH_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

const float kPi = 3.14159265358979f;
const float kInvPi = 0.318309886183791f;

VOXGI_FN float dot3(vec3 a, vec3 b) {
  precise float r = (a.x * b.x + a.y * b.y) + a.z * b.z;
  return r;
}

VOXGI_FN vec3 cross3(vec3 a, vec3 b) {
  precise vec3 r = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return r;
}

VOXGI_FN float length3(vec3 a) {
  precise float r = sqrt(dot3(a, a));
  return r;
}

// a / |a|, or 0 for a zero vector.
VOXGI_FN vec3 normalize3(vec3 a) {
  precise float len = length3(a);
  if (len == 0.0f) return vec3(0.0f);
  precise vec3 r = a / len;
  return r;
}

VOXGI_NAMESPACE_END
#endif
