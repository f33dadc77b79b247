// Lets the headers in shaders/shared compile both as GLSL 4.50 and as C++20 (with glm), so the CPU
// reference and the shaders run literally the same arithmetic. Rules for shared code:
// - float literals carry the f suffix (a bare 0.5 is a double in C++);
// - dot/cross are written out (dot3/cross3) so both sides sum in the same order;
// - results that CPU/GPU agreement depends on are declared `precise` (no fused multiply-add on the
//   GPU; the C++ side is built with -ffp-contract=off);
// - functions are declared VOXGI_FN, out-parameters OUT(T);
// - only + - * / sqrt floor min max abs clamp are bit-exact across backends (on llvmpipe);
//   transcendentals (pow, exp, log2, tan) are computed on the host where possible, and a buffer
//   that depends on one states it in its comparison (validation/comparisons.inc).
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

// Functions that read volumes: in C++ a template over an accessor object `volumes` (see cpu/), in
// GLSL plain functions the shader defines before including the shared header. Shared code declares
// them VOLUME_FN with VOLUMES_IN as the first parameter, passes VOLUMES on, and reads with
// FETCH(name)(args).
#ifdef __cplusplus
#define VOLUME_FN          \
  template <class Volumes> \
  inline
#define VOLUMES_IN const Volumes &volumes,
#define VOLUMES volumes,
#define FETCH(fn) volumes.fn
#else
#define VOLUME_FN
#define VOLUMES_IN
#define VOLUMES
#define FETCH(fn) fn
#endif

#endif
