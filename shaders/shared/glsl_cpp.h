// Lets the headers in shaders/shared compile both as GLSL 4.50 and as C++20 (with glm), so the CPU
// reference and the shaders run literally the same arithmetic. Rules for shared code:
// - float literals carry the f suffix (a bare 0.5 is a double in C++);
// - dot/cross are written out (dot3/cross3) so both sides sum in the same order;
// - results that CPU/GPU agreement depends on are declared `precise` (no fused multiply-add on the
//   GPU; the C++ side is built with -ffp-contract=off);
// - functions are declared VOXGI_FN, out-parameters OUT(T).
#ifndef VOXGI_GLSL_CPP_H
#define VOXGI_GLSL_CPP_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#define precise
#define VOXGI_FN inline
#define OUT(T) T&
#define VOXGI_NAMESPACE_BEGIN \
  namespace voxgi::shared {   \
  using namespace glm;        \
  using uint = unsigned int;
#define VOXGI_NAMESPACE_END }
#else
#define VOXGI_FN
#define OUT(T) out T
#define VOXGI_NAMESPACE_BEGIN
#define VOXGI_NAMESPACE_END
#endif

#endif
