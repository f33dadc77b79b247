// propagate_lanes.h's kernel for one instruction set, included once by each of
// propagate_lanes_{sse2,avx2,avx512}.cpp with VOXGI_LANES_ARCH set to an xsimd arch and
// VOXGI_LANES_SUFFIX to its entry points' suffix (Sse2: propagateRowsSse2). Everything else
// here is in an unnamed namespace, so no inline function compiled for AVX2 or AVX-512 can stand in
// for another unit's (tests/simd_symbols_test.cmake checks those objects).
#include <utility>

#include <xsimd/xsimd.hpp>

#include "cpu/lpv/propagate_lanes.h"

namespace voxgi::cpu::lpv_lanes {
namespace {

using Arch = VOXGI_LANES_ARCH;
using Lanes = xsimd::batch<float, Arch>;
using LaneMask = xsimd::batch_bool<float, Arch>;
constexpr int kWidth = int(Lanes::size);

// glm's max and min (shared::propagateCell's max and clamp), with their choices at ties and zeros.
Lanes glmMax(Lanes x, Lanes y) {
  return xsimd::select(x < y, y, x);
}
Lanes glmMin(Lanes x, Lanes y) {
  return xsimd::select(y < x, y, x);
}

Lanes load(const float* p) {
  return Lanes::load_unaligned(p);
}

// shared::blockingBetween for the lanes' cells x0 .. x0 + W - 1 of row (y, z): the corners in the
// kernel's order, each a row of the padded geometry planes, summed from +0 and scaled once.
void blend(const Step& s, int x0, int y, int z, const int o[3], Lanes out[4]) {
  const int n = s.n;
  float weight = 1.0f;
  for (int a = 0; a < 3; ++a)
    if (o[a] == 0) weight = weight * 0.5f;
  const int c[3] = {x0, y, z};
  Lanes sum[4] = {Lanes(0.0f), Lanes(0.0f), Lanes(0.0f), Lanes(0.0f)};
  for (int corner = 0; corner < 8; ++corner) {
    int g[3];
    bool used = true;
    for (int a = 0; a < 3; ++a) {
      const int bit = (corner >> a) & 1;
      if (o[a] == 0)
        g[a] = c[a] - 1 + bit;
      else {
        used = used && bit == 0;
        g[a] = c[a] - (o[a] + 1) / 2;
      }
    }
    if (!used) continue;
    const size_t row = size_t(g[1] + 1) + size_t(n + 2) * size_t(g[2] + 1);
    const float* p = s.blocking + row * 4 * size_t(s.stride) + size_t(g[0] + 1);
    for (int k = 0; k < 4; ++k) sum[k] = sum[k] + load(p + size_t(k) * size_t(s.stride));
  }
  for (int k = 0; k < 4; ++k) out[k] = sum[k] * Lanes(weight);
}

// The kernel's visibility 1 - clamp(blend . f.blocking, 0, 1) for the lanes' cells, the blend
// fetched when the entry's offset differs from the one it was last fetched for (as the kernel).
Lanes visibilityOf(const Step& s, const Entry& f, int x0, int y, int z, int blockedFor[3],
                   Lanes blocking[4]) {
  const int o[3] = {f.dx, f.dy, f.dz};
  if (o[0] != blockedFor[0] || o[1] != blockedFor[1] || o[2] != blockedFor[2]) {
    blend(s, x0, y, z, o, blocking);
    blockedFor[0] = o[0], blockedFor[1] = o[1], blockedFor[2] = o[2];
  }
  const Lanes blocked = blocking[0] * Lanes(f.blocking[0]) + blocking[1] * Lanes(f.blocking[1]) +
                        blocking[2] * Lanes(f.blocking[2]) + blocking[3] * Lanes(f.blocking[3]);
  return Lanes(1.0f) - glmMin(glmMax(blocked, Lanes(0.0f)), Lanes(1.0f));
}

// Every entry's visibility for the cells of rows [rowBegin, rowEnd) into `out` (a row's entries
// one after another), which the occluded steps then read instead.
void visibilityRowsOf(const Step& s, float* out, int rowBegin, int rowEnd) {
  const int n = s.n;
  for (int row = rowBegin; row < rowEnd; ++row) {
    const int y = row % n, z = row / n;
    const size_t rowAt = size_t(row) * size_t(s.entryCount) * size_t(s.stride) + 1;
    for (int x0 = 0; x0 < n; x0 += kWidth) {
      int blockedFor[3] = {0, 0, 0};
      Lanes blocking[4];
      for (int e = 0; e < s.entryCount; ++e)
        visibilityOf(s, s.entries[e], x0, y, z, blockedFor, blocking)
            .store_unaligned(out + rowAt + size_t(e) * size_t(s.stride) + size_t(x0));
    }
  }
}

// dst[c C + i] += flux[c] x r[i] for the three colours and the coefficients I..., the non-zero
// ones of the entry's lobe: unrolled with the indices known, so that the sums stay in registers
// (with 9 coefficients the 18 that ever change). Each sum gets one product per entry, as in the
// kernel; which sum is added to first changes no bit.
template <int C, int... I>
void reproject(Lanes* dst, const Lanes* flux, const float* r, std::integer_sequence<int, I...>) {
  for (int c = 0; c < 3; ++c) ((dst[c * C + I] = dst[c * C + I] + flux[c] * Lanes(r[I])), ...);
}

template <int C>
void reprojectAny(Lanes* dst, const Lanes* flux, const Entry& f) {
  const float* r = f.reprojected;
  if constexpr (C == 4) {
    switch (f.lobe) {
      case Entry::kLobeX:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 3>());
      case Entry::kLobeY:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 1>());
      case Entry::kLobeZ:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 2>());
    }
  } else {
    switch (f.lobe) {
      case Entry::kLobeX:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 3, 6, 8>());
      case Entry::kLobeY:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 1, 6, 8>());
      case Entry::kLobeZ:
        return reproject<C>(dst, flux, r, std::integer_sequence<int, 0, 2, 6>());
    }
  }
}

template <int C>
void propagateRows(const Step& s, int rowBegin, int rowEnd) {
  const int n = s.n;
  const size_t stride = size_t(s.stride), rowFloats = size_t(3 * C) * stride;
  const bool occlude = s.visibility != nullptr || s.blocking != nullptr;
  alignas(64) float laneIndex[kWidth];
  for (int j = 0; j < kWidth; ++j) laneIndex[j] = float(j);
  const Lanes lanes = Lanes::load_aligned(laneIndex);
  for (int row = rowBegin; row < rowEnd; ++row) {
    const int y = row % n, z = row / n;
    const size_t rowAt = size_t(row) * rowFloats + 1;
    const float* visibilityRow =
        s.visibility ? s.visibility + size_t(row) * size_t(s.entryCount) * stride + 1 : nullptr;
    for (int x0 = 0; x0 < n; x0 += kWidth) {
      // Unrolled, so that every index is a constant and the sums live in registers.
      Lanes dst[3 * C];
#pragma GCC unroll 32
      for (int w = 0; w < 3 * C; ++w) dst[w] = Lanes(0.0f);
      int blockedFor[3] = {0, 0, 0};  // the offset `blocking` holds (0: none yet)
      Lanes blocking[4];
      for (int e = 0; e < s.entryCount; ++e) {
        const Entry& f = s.entries[e];
        const int sy = y - f.dy, sz = z - f.dz;
        if (sy < 0 || sy >= n || sz < 0 || sz >= n) continue;
        // The source row; lanes whose source x is outside the grid read the pads' +0.
        const float* src =
            s.previous + (size_t(sy) + size_t(n) * size_t(sz)) * rowFloats + size_t(1 + x0 - f.dx);
        Lanes visibility(1.0f);
        if (s.visibility)
          visibility = load(visibilityRow + size_t(e) * stride + size_t(x0));
        else if (s.blocking)
          visibility = visibilityOf(s, f, x0, y, z, blockedFor, blocking);
        // The colours' sums side by side, each in the kernel's order. The kernel skips a zero
        // basis value; adding its +-0 product to a sum that started at +0 changes no bit.
        Lanes flux[3] = {Lanes(0.0f), Lanes(0.0f), Lanes(0.0f)};
        for (int i = 0; i < C; ++i) {
          const Lanes sampled(f.sampled[i]);
          for (int c = 0; c < 3; ++c)
            flux[c] = flux[c] + load(src + size_t(c * C + i) * stride) * sampled;
        }
        for (int c = 0; c < 3; ++c) {
          if (s.clampNegative) flux[c] = glmMax(flux[c], Lanes(0.0f));
          // The kernel multiplies by a visibility of 1 without occlusion: x * 1 is x.
          if (occlude) flux[c] = flux[c] * visibility;
        }
        reprojectAny<C>(dst, flux, f);
      }
      // Lanes past the grid's end hold light spilled from the last cell: the pads stay +0.
      const LaneMask inside = lanes < Lanes(float(n - x0));
#pragma GCC unroll 32
      for (int w = 0; w < 3 * C; ++w) {
        const size_t at = rowAt + size_t(w) * stride + size_t(x0);
        const Lanes value = xsimd::select(inside, dst[w], Lanes(0.0f));
        value.store_unaligned(s.next + at);
        if (s.accumulated) (load(s.accumulated + at) + value).store_unaligned(s.accumulated + at);
      }
    }
  }
}

}  // namespace

#define VOXGI_LANES_PASTE(name, suffix) name##suffix
#define VOXGI_LANES_NAME(name, suffix) VOXGI_LANES_PASTE(name, suffix)

void VOXGI_LANES_NAME(visibilityRows, VOXGI_LANES_SUFFIX)(const Step& step, float* visibility,
                                                          int rowBegin, int rowEnd) {
  visibilityRowsOf(step, visibility, rowBegin, rowEnd);
}

void VOXGI_LANES_NAME(propagateRows, VOXGI_LANES_SUFFIX)(const Step& step, int rowBegin,
                                                         int rowEnd) {
  if (step.coefficients == 4)
    propagateRows<4>(step, rowBegin, rowEnd);
  else
    propagateRows<9>(step, rowBegin, rowEnd);
}

}  // namespace voxgi::cpu::lpv_lanes
