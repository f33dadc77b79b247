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

VOXGI_NAMESPACE_END
#endif
