// Real spherical harmonics up to band 2, and the clamped-cosine lobe, for light propagation
// volumes: what injection, propagation and shading of both backends evaluate. Martin 2012 prints
// no basis, sign convention or order; this is Sloan's real basis with the Condon-Shortley phase
// [Sloan 2008, App. A2], index i = l(l+1)+m, the order the NVIDIA-derived LPV code stores
// bands 0-1 in: (K0, -K1 y, K1 z, -K1 x) [Martin 2012, §3.2.1].
#ifndef VOXGI_LPV_SH_H
#define VOXGI_LPV_SH_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

const float kShK0 = 0.282094791773878f;  // 1 / (2 sqrt(pi))
const float kShK1 = 0.488602511902920f;  // sqrt(3) / (2 sqrt(pi))
const float kShK2 = 1.092548430592079f;  // sqrt(15) / (2 sqrt(pi))
const float kShK3 = 0.315391565252520f;  // sqrt(5) / (4 sqrt(pi))
const float kShK4 = 0.546274215296040f;  // sqrt(15) / (4 sqrt(pi))

// The zonal coefficients of max(0, cos) scaled by sqrt(4 pi / (2l + 1)): A_l = pi, 2 pi / 3,
// pi / 4 [Martin 2012, Eq. 3.1-3.2; Ramamoorthi & Hanrahan 2001], so a lobe about n is A_l Y_lm(n).
const float kShCosine0 = 3.14159265358979f;
const float kShCosine1 = 2.09439510239320f;
const float kShCosine2 = 0.785398163397448f;

// Y_i(d) for a unit vector d, i in [0, 9).
VOXGI_FN float shBasis(int i, vec3 d) {
  if (i == 0) return kShK0;
  if (i == 1) return -kShK1 * d.y;
  if (i == 2) return kShK1 * d.z;
  if (i == 3) return -kShK1 * d.x;
  if (i == 4) return kShK2 * (d.x * d.y);
  if (i == 5) return -kShK2 * (d.y * d.z);
  if (i == 6) return kShK3 * (3.0f * (d.z * d.z) - 1.0f);
  if (i == 7) return -kShK2 * (d.x * d.z);
  return kShK4 * (d.x * d.x - d.y * d.y);
}

// The band l of coefficient i.
VOXGI_FN int shBand(int i) {
  return i == 0 ? 0 : (i < 4 ? 1 : 2);
}

// Coefficient i of the clamped-cosine lobe max(0, n . w) about the unit vector n.
VOXGI_FN float shCosineLobe(int i, vec3 n) {
  int l = shBand(i);
  float a = l == 0 ? kShCosine0 : (l == 1 ? kShCosine1 : kShCosine2);
  return a * shBasis(i, n);
}

VOXGI_NAMESPACE_END

#endif
