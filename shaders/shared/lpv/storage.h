// How the light propagation volumes store values (lpv.storage), shared by propagate's kernel and
// its accessors on both backends.
#ifndef VOXGI_LPV_STORAGE_H
#define VOXGI_LPV_STORAGE_H
#include "../half_float.h"
#include "lpv_types.h"

VOXGI_NAMESPACE_BEGIN

// A value as the volumes store it: with lpv.storage=f16, the nearest half in units of the
// power-of-two scale p.storageScale (so LPV_0's largest coefficient is at most 1 and the range of a
// half, 6e-5 .. 65504 with 11 significant bits, covers what propagation needs).
VOXGI_FN float storedValue(float v, PropagateParams p) {
  if (p.halfPrecision == 0) return v;
  precise float units = v * p.inverseStorageScale;
  precise float stored = roundToHalf(units) * p.storageScale;
  return stored;
}

// The accumulated volume after adding a step's stored value v to acc (an add-blend into a half
// target rounds again).
VOXGI_FN float accumulatedValue(float acc, float v, PropagateParams p) {
  precise float sum = acc + v;
  return storedValue(sum, p);
}

// lpv.storage=f16 on the GPU packs the stored values two halves a 32-bit word (the low half
// first), a cell's values padded to whole words so that no two cells (invocations) share a word.
VOXGI_FN int packedCellWords(int values) {
  return (values + 1) / 2;
}

// Stored value `part` (0: the low half, 1: the high) of `word`.
VOXGI_FN float unpackStored(uint word, int part, PropagateParams p) {
  uint h = part == 0 ? word & 0xffffu : word >> 16;
  precise float v = halfValue(h) * p.storageScale;
  return v;
}

// `word` with its half `part` replaced by stored value v (storedValue's: a half in units of the
// storage scale, so that the packing is exact).
VOXGI_FN uint packStored(uint word, int part, float v, PropagateParams p) {
  precise float units = v * p.inverseStorageScale;
  uint h = halfBits(units);
  return part == 0 ? (word & 0xffff0000u) | h : (word & 0xffffu) | (h << 16);
}

VOXGI_NAMESPACE_END
#endif
