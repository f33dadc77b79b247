// The CPU's fast path for lpv/propagate: shared::propagateCell for a run of cells along x at
// once, one cell per SIMD lane (xsimd: 4 lanes on SSE2, 8 on AVX2, 16 on AVX-512, chosen at run
// time by cpu/simd.h). Each lane does exactly the operations the shared kernel does for its cell,
// in the same order and without fused multiply-adds, so the volumes are bit for bit the kernel's
// on every instruction set (tests/lpv/propagate_lanes_test.cpp). What the lanes change is the
// layout (Layout): a row of cells along x holds each coefficient word's values one run after
// another, padded along x with zeros, so that a neighbour's words are unaligned loads a run apart
// and a source outside the grid reads +0, which adds nothing (the shared kernel skips it;
// docs/stages/lpv/propagate.md).
//
// This header is included by the AVX2 and AVX-512 translation units: it holds plain data only
// (no glm, no standard-library templates whose inline code the linker could take from them).
#pragma once

#include <cstddef>

namespace voxgi::cpu::lpv_lanes {

// The padded layout of an n^3 volume of `words` floats per cell: rows y + n z, each `words` runs
// of `stride` floats (n rounded up to 16 lanes, plus a zero on each side; cell x at 1 + x), word
// w's run at w x stride in its row.
struct Layout {
  int n = 0;
  int stride = 0;
  explicit Layout(int cells) : n(cells), stride((cells + 15) / 16 * 16 + 2) {}
  size_t volumeFloats(int words) const {
    return size_t(stride) * size_t(words) * size_t(n) * size_t(n);
  }
  size_t index(int words, int row, int word, int x) const {
    return (size_t(row) * size_t(words) + size_t(word)) * size_t(stride) + size_t(1 + x);
  }
};

// One face entry (shared::PropagationEntry) as the lanes read it.
struct Entry {
  // Which coefficients of `reprojected` are non-zero: those of a lobe about the x, y or z axis,
  // the normal of the destination's face (with 9 coefficients 4, 5 and 7 are zero for all three,
  // so the lanes never hold those sums).
  enum Lobe : int { kLobeX, kLobeY, kLobeZ };
  int dx, dy, dz;  // destination - source
  int lobe;
  float sampled[9];
  float reprojected[9];
  float blocking[4];
};

// One gather step over rows [rowBegin, rowEnd) (row = y + n z).
struct Step {
  int n = 0;
  int coefficients = 4;             // C: 4 or 9
  int stride = 0;                   // Layout::stride
  const float* previous = nullptr;  // Layout of 3C words, pads zero
  float* next = nullptr;            // the same: each row's cells written, pads written zero
  float* accumulated = nullptr;     // the same: next added to it; null to leave it (f16 storage)
  // The geometry volume: Layout of 4 words over (n+2)^2 rows (y, z from -1), zero outside the
  // grid; null: no occlusion.
  const float* blocking = nullptr;
  // Layout of one word per entry: what blocking gives, read instead of it where not null
  // (visibilityRows*).
  const float* visibility = nullptr;
  const Entry* entries = nullptr;
  int entryCount = 0;
  bool clampNegative = false;
};

// The visibility of every entry for rows [rowBegin, rowEnd) from step.blocking, bit for bit what
// propagateRows* computes for an occluded step without it.
void visibilityRowsSse2(const Step& step, float* visibility, int rowBegin, int rowEnd);
void visibilityRowsAvx2(const Step& step, float* visibility, int rowBegin, int rowEnd);
void visibilityRowsAvx512(const Step& step, float* visibility, int rowBegin, int rowEnd);

void propagateRowsSse2(const Step& step, int rowBegin, int rowEnd);
void propagateRowsAvx2(const Step& step, int rowBegin, int rowEnd);
void propagateRowsAvx512(const Step& step, int rowBegin, int rowEnd);

}  // namespace voxgi::cpu::lpv_lanes
