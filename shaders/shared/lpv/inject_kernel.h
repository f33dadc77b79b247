// inject's arithmetic: one VPL's clamped-cosine lobe as fixed-point SH coefficients, and the
// cell it lands in [Martin 2012, §3.2.1; Kaplanyan & Dachsbacher 2010]. The lobe of a VPL of flux
// F about n is (F / pi) A_l Y_lm(n), which emits exactly F (Martin writes F A_l Y_lm, a factor pi
// too much: docs/lpv.md). Scatters add these integers, so the sums do not depend on order.
#ifndef VOXGI_LPV_INJECT_KERNEL_H
#define VOXGI_LPV_INJECT_KERNEL_H
#include "lpv_types.h"
#include "sh.h"

VOXGI_NAMESPACE_BEGIN

// A_l / pi for the band of coefficient i: 1, 2/3, 1/4.
VOXGI_FN float shLobeOverPi(int i) {
  int l = shBand(i);
  return l == 0 ? 1.0f : (l == 1 ? 0.666666667f : 0.25f);
}

// The cell of the VPL; may lie outside the grid (its light is then lost).
VOXGI_FN ivec3 vplCell(Vpl v) {
  return ivec3(floor(vec3(v.position)));
}

// Coefficient i of colour c of the VPL's lobe in fixed point (units 1 / scale[c]).
VOXGI_FN int vplCoefficient(Vpl v, int c, int i, vec4 scale) {
  precise float units = v.flux[c] * scale[c];
  precise float value = units * (shLobeOverPi(i) * shBasis(i, vec3(v.normal)));
  return int(floor(value + 0.5f));
}

// A fixed-point sum as intensity.
VOXGI_FN float injectedIntensity(int sum, float scale) {
  precise float value = float(sum) / scale;
  return value;
}

VOXGI_NAMESPACE_END
#endif
