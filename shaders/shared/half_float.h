// Rounding a float to the nearest IEEE half (binary16) value, round-to-nearest-even, overflow to
// infinity, halves below 2^-14 subnormal: what storing it in an RGBA16F texture does (lpv.storage
// =f16, [Martin 2012, §5.8]). Written with bit operations and one exactly rounded addition, so the
// CPU and any GPU give the same bits (GLSL's packHalf2x16 leaves the rounding mode open).
#ifndef VOXGI_HALF_FLOAT_H
#define VOXGI_HALF_FLOAT_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

VOXGI_FN float roundToHalf(float x) {
  uint bits = floatBitsToUint(x);
  uint sign = bits & 0x80000000u;
  uint magnitude = bits & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) return x;                                    // infinity or NaN
  if (magnitude >= 0x477ff000u) return uintBitsToFloat(sign | 0x7f800000u);  // >= 65520
  if (magnitude >= 0x38800000u) {  // >= 2^-14: keep 10 of the 23 mantissa bits, ties to even
    uint rounded = (magnitude + 0x00000fffu + ((magnitude >> 13) & 1u)) & 0xffffe000u;
    return uintBitsToFloat(sign | rounded);
  }
  // Subnormal halves are multiples of 2^-24, the spacing of floats in [0.5, 1): adding 0.5 rounds
  // to it (ties to even), and subtracting it again is exact.
  precise float shifted = uintBitsToFloat(magnitude) + 0.5f;
  precise float q = shifted - 0.5f;
  return uintBitsToFloat(sign | floatBitsToUint(q));
}

// The binary16 bits of x, which must hold a half value already (roundToHalf's): exact, so that
// packing leaves nothing to the platform (GLSL's packHalf2x16 may flush subnormals).
VOXGI_FN uint halfBits(float x) {
  uint bits = floatBitsToUint(x);
  uint sign = (bits >> 16) & 0x8000u;
  uint magnitude = bits & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) return sign | 0x7c00u | (magnitude > 0x7f800000u ? 0x200u : 0u);
  if (magnitude >= 0x38800000u) return sign | ((magnitude - 0x38000000u) >> 13);
  precise float units = uintBitsToFloat(magnitude) * 16777216.0f;  // a subnormal: k 2^-24
  return sign | uint(units);
}

// The value of binary16 bits h (the low 16 bits), exactly.
VOXGI_FN float halfValue(uint h) {
  uint sign = (h & 0x8000u) << 16;
  uint magnitude = h & 0x7fffu;
  if (magnitude >= 0x7c00u)
    return uintBitsToFloat(sign | 0x7f800000u | ((magnitude & 0x3ffu) << 13));
  if (magnitude >= 0x0400u) return uintBitsToFloat(sign | ((magnitude << 13) + 0x38000000u));
  precise float v = float(magnitude) * uintBitsToFloat(0x33800000u);  // k 2^-24
  return uintBitsToFloat(sign | floatBitsToUint(v));
}

// An RGBA value rounded to halves, component by component.
VOXGI_FN vec4 roundToHalf4(vec4 v) {
  return vec4(roundToHalf(v.x), roundToHalf(v.y), roundToHalf(v.z), roundToHalf(v.w));
}

// An RGBA value as two words of halves, each rounded to the nearest: x and y in the first word, z
// and w in the second, the low half first (the octree's light pools, common/svo/stages.inc; the
// layout of an f16 buffer in common/buffer.h).
VOXGI_FN uvec2 packHalves(vec4 v) {
  vec4 h = roundToHalf4(v);
  return uvec2(halfBits(h.x) | (halfBits(h.y) << 16u), halfBits(h.z) | (halfBits(h.w) << 16u));
}

// packHalves' words back to their values, exactly.
VOXGI_FN vec4 unpackHalves(uvec2 w) {
  return vec4(halfValue(w.x & 0xffffu), halfValue(w.x >> 16u), halfValue(w.y & 0xffffu),
              halfValue(w.y >> 16u));
}

VOXGI_NAMESPACE_END
#endif
