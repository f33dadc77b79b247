// propagate's arithmetic: one gather step into one cell [Kaplanyan & Dachsbacher 2010, §4;
// Martin 2012, §3.2.3, §4.2]. For every face entry f of a neighbour source cell x - o: the
// source's intensity toward the face's centre, I_f = sum_i c_i Y_i(omega_f), attenuated by the
// geometry volume at the point where light leaves the source cell, re-emitted as the face's
// clamped-cosine lobe (PropagationEntry::reprojected holds its weight: Omega_f / pi, or the
// thesis's Omega_f / (4 pi)). Sums run in the entry table's order on both backends. Products with
// a zero weight are skipped: the axis-aligned lobes are zero in 2 of 4 (5 or 6 of 9) coefficients,
// and so is the source's basis toward a face straight ahead; a sum starts at +0, so adding the
// product's +-0 would change no bit of it (for finite values), and skipping it is the same kernel.
// The CPU's lanes (cpu/lpv/propagate_lanes.h) skip the same products.
//
// Reads FETCH(entryAt)(e) -> PropagationEntry, FETCH(intensityAt)(cell, word) -> float (the
// previous step; word = colour * C + i), FETCH(blockingAt)(g) -> vec4 (0 outside the grid), and
// FETCH(coefficientCount)() -> C (p.coefficients; a constant in the CPU's accessor, so the compiler
// unrolls the coefficient loops there — the same operations in the same order) and
// FETCH(colourCount)() -> 3 (the kernel tests propagate one colour).
#ifndef VOXGI_LPV_PROPAGATE_KERNEL_H
#define VOXGI_LPV_PROPAGATE_KERNEL_H
#include "lpv_types.h"
#include "storage.h"

VOXGI_NAMESPACE_BEGIN

// The geometry volume at p = x_src + o/2, the point the central ray from source x - o leaves its
// cell through (a face centre, an edge midpoint or a corner: [Martin 2012, §4.2] leaves it open,
// docs/lpv.md). GV cell g sits at corner g + 1, so along an axis with o = 0 p lies halfway
// between GV cells x - 1 and x, and otherwise on GV cell x - (o + 1) / 2: a blend of 4, 2 or 1.
VOLUME_FN vec4 blockingBetween(VOLUMES_IN ivec3 x, ivec3 o) {
  precise vec4 sum = vec4(0.0f);
  float weight = 1.0f;
  for (int a = 0; a < 3; ++a)
    if (o[a] == 0) weight = weight * 0.5f;
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 g = x;
    bool used = true;
    for (int a = 0; a < 3; ++a) {
      int bit = (corner >> a) & 1;
      if (o[a] == 0)
        g[a] = x[a] - 1 + bit;
      else {
        used = used && bit == 0;
        g[a] = x[a] - (o[a] + 1) / 2;
      }
    }
    if (used) sum = sum + FETCH(blockingAt)(g);
  }
  precise vec4 blend = sum * weight;
  return blend;
}

// Writes the step's value of cell x, as stored, through FETCH(storeIntensity)(x, word, value).
VOLUME_FN void propagateCell(VOLUMES_IN ivec3 x, PropagateParams p) {
  int n = p.resolution, coefficients = FETCH(coefficientCount)(), colours = FETCH(colourCount)();
  bool occlude = p.occlude != 0, clampNegative = p.clampNegative != 0;
  float dst[27];
  for (int w = 0; w < 27; ++w) dst[w] = 0.0f;
  ivec3 blockedFor = ivec3(0);  // the offset `blocking` was fetched for (0: none yet)
  vec4 blocking = vec4(0.0f);
  for (int e = 0; e < p.entryCount; ++e) {
    PropagationEntry f = FETCH(entryAt)(e);
    ivec3 o = ivec3(f.offset);
    ivec3 src = x - o;
    if (any(lessThan(src, ivec3(0))) || any(greaterThanEqual(src, ivec3(n)))) continue;
    precise float visibility = 1.0f;
    if (occlude) {
      if (o != blockedFor) {
        blocking = blockingBetween(VOLUMES x, o);
        blockedFor = o;
      }
      precise float blocked = blocking.x * f.blocking[0] + blocking.y * f.blocking[1] +
                              blocking.z * f.blocking[2] + blocking.w * f.blocking[3];
      visibility = 1.0f - clamp(blocked, 0.0f, 1.0f);
    }
    for (int c = 0; c < colours; ++c) {
      precise float intensity = 0.0f;
      for (int i = 0; i < coefficients; ++i)
        if (f.sampled[i] != 0.0f)
          intensity = intensity + FETCH(intensityAt)(src, c * coefficients + i) * f.sampled[i];
      if (clampNegative) intensity = max(intensity, 0.0f);
      precise float flux = intensity * visibility;
      for (int i = 0; i < coefficients; ++i)
        if (f.reprojected[i] != 0.0f)
          dst[c * coefficients + i] = dst[c * coefficients + i] + flux * f.reprojected[i];
    }
  }
  for (int w = 0; w < colours * coefficients; ++w)
    FETCH(storeIntensity)(x, w, storedValue(dst[w], p));
}

VOXGI_NAMESPACE_END
#endif
