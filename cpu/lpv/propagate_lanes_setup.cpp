#include "cpu/lpv/propagate_lanes_setup.h"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "common/parallel.h"

namespace voxgi::cpu::lpv_lanes {
namespace {

size_t cellWord(const Layout& l, int words, int row, int x, int w) {
  return (size_t(row) * size_t(l.n) + size_t(x)) * size_t(words) + size_t(w);
}

// The lobe whose non-zero coefficients are exactly those of `r`: the axis's band-0 and band-1
// terms, and with 9 coefficients the band-2 ones it does not zero.
int lobeOf(const float* r, int coefficients) {
  struct Lobe {
    int lobe;
    std::vector<int> nonZero;
  };
  const std::vector<Lobe> lobes = coefficients == 4
                                      ? std::vector<Lobe>{{Entry::kLobeX, {0, 3}},
                                                          {Entry::kLobeY, {0, 1}},
                                                          {Entry::kLobeZ, {0, 2}}}
                                      : std::vector<Lobe>{{Entry::kLobeX, {0, 3, 6, 8}},
                                                          {Entry::kLobeY, {0, 1, 6, 8}},
                                                          {Entry::kLobeZ, {0, 2, 6}}};
  for (const Lobe& l : lobes) {
    bool match = true;
    for (int i = 0; i < coefficients; ++i)
      match = match && (r[i] != 0.0f) ==
                           (std::find(l.nonZero.begin(), l.nonZero.end(), i) != l.nonZero.end());
    if (match) return l.lobe;
  }
  throw std::logic_error("lpv/propagate: a face entry's lobe is not about an axis");
}

}  // namespace

void toLayout(const Layout& l, int words, const float* cells, float* out) {
  parallelFor(tbb::blocked_range<int>(0, l.n * l.n), [&](const auto& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row)
      for (int w = 0; w < words; ++w)
        for (int x = 0; x < l.n; ++x)
          out[l.index(words, row, w, x)] = cells[cellWord(l, words, row, x, w)];
  });
}

void fromLayout(const Layout& l, int words, const float* in, float* cells) {
  parallelFor(tbb::blocked_range<int>(0, l.n * l.n), [&](const auto& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row)
      for (int w = 0; w < words; ++w)
        for (int x = 0; x < l.n; ++x)
          cells[cellWord(l, words, row, x, w)] = in[l.index(words, row, w, x)];
  });
}

std::vector<float> geometryLayout(const Layout& l, const float* blocking) {
  const int n = l.n, side = n + 2;
  std::vector<float> out(size_t(side) * size_t(side) * 4 * size_t(l.stride), 0.0f);
  for (int row = 0; row < n * n; ++row) {
    const int padded = (row % n + 1) + side * (row / n + 1);
    for (int k = 0; k < 4; ++k)
      for (int x = 0; x < n; ++x)
        out[l.index(4, padded, k, x)] = blocking[cellWord(l, 4, row, x, k)];
  }
  return out;
}

std::vector<Entry> laneEntries(const std::vector<shared::PropagationEntry>& entries,
                               int coefficients) {
  std::vector<Entry> out;
  for (const shared::PropagationEntry& e : entries) {
    Entry f{e.offset.x, e.offset.y, e.offset.z, lobeOf(e.reprojected, coefficients), {}, {}, {}};
    std::memcpy(f.sampled, e.sampled, sizeof f.sampled);
    std::memcpy(f.reprojected, e.reprojected, sizeof f.reprojected);
    std::memcpy(f.blocking, e.blocking, sizeof f.blocking);
    out.push_back(f);
  }
  return out;
}

void propagateRows(SimdLevel level, const Step& step, int rowBegin, int rowEnd) {
  switch (level) {
    case SimdLevel::avx512:
      return propagateRowsAvx512(step, rowBegin, rowEnd);
    case SimdLevel::avx2:
      return propagateRowsAvx2(step, rowBegin, rowEnd);
    case SimdLevel::sse2:
      return propagateRowsSse2(step, rowBegin, rowEnd);
  }
}

void visibilityRows(SimdLevel level, const Step& step, float* visibility, int rowBegin,
                    int rowEnd) {
  switch (level) {
    case SimdLevel::avx512:
      return visibilityRowsAvx512(step, visibility, rowBegin, rowEnd);
    case SimdLevel::avx2:
      return visibilityRowsAvx2(step, visibility, rowBegin, rowEnd);
    case SimdLevel::sse2:
      return visibilityRowsSse2(step, visibility, rowBegin, rowEnd);
  }
}

}  // namespace voxgi::cpu::lpv_lanes
