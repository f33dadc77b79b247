// log2, exp2, pow and acos from + - * / sqrt, frexp and ldexp only, so the cone tracer's levels,
// opacity correction and specular lobes agree bit for bit between the CPU and llvmpipe, and to a
// few ULP on hardware (whose built-in transcendentals differ by vendor). Accuracy: log2Approx
// within 2e-7 absolute, exp2Approx within 3e-7 relative, acosApprox within 3e-8 (Abramowitz and
// Stegun 4.4.46) — far below what moves a cone sample.
#ifndef VOXGI_APPROX_MATH_H
#define VOXGI_APPROX_MATH_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// log2(x) for finite x > 0: x = m 2^e with m in [sqrt(1/2), sqrt(2)), then the atanh series of
// ln(m) = 2 atanh((m - 1) / (m + 1)) to s^9 (|s| <= 0.172, remainder below 4e-10).
VOXGI_FN float log2Approx(float x) {
  int e = 0;
  precise float m = frexp(x, e);
  if (m < 0.70710678f) {
    m = m * 2.0f;
    e = e - 1;
  }
  precise float s = (m - 1.0f) / (m + 1.0f);
  precise float s2 = s * s;
  precise float series =
      s * (1.0f + s2 * (0.33333333f + s2 * (0.2f + s2 * (0.14285714f + s2 * 0.11111111f))));
  precise float r = float(e) + series * 2.8853901f;  // 2 / ln 2
  return r;
}

// 2^x for x in [-126, 127] (clamped): 2^floor(x) exactly (ldexp) times 2^f, f in [0, 1), from the
// Taylor series of e^g, g = (f - 1/2) ln 2, to g^7 (remainder below 6e-9), times sqrt(2).
VOXGI_FN float exp2Approx(float x) {
  precise float c = clamp(x, -126.0f, 127.0f);
  precise float i = floor(c);
  precise float g = (c - i - 0.5f) * 0.69314718f;
  precise float p =
      1.0f +
      g * (1.0f +
           g * (0.5f + g * (0.16666667f +
                            g * (0.041666667f +
                                 g * (0.0083333333f + g * (0.0013888889f + g * 0.00019841270f))))));
  precise float r = ldexp(p * 1.4142136f, int(i));
  return r;
}

// x^y for x >= 0 and y > 0 (0 for x <= 0).
VOXGI_FN float powApprox(float x, float y) {
  if (x <= 0.0f) return 0.0f;
  precise float r = exp2Approx(y * log2Approx(x));
  return r;
}

// acos(x) for x in [-1, 1] (clamped).
VOXGI_FN float acosApprox(float x) {
  precise float a = min(abs(x), 1.0f);
  precise float poly =
      1.5707963050f +
      a * (-0.2145988016f +
           a * (0.0889789874f +
                a * (-0.0501743046f +
                     a * (0.0308918810f +
                          a * (-0.0170881256f + a * (0.0066700901f + a * -0.0012624911f))))));
  precise float r = sqrt(1.0f - a) * poly;
  if (x < 0.0f) r = 3.14159265f - r;
  return r;
}

VOXGI_NAMESPACE_END
#endif
