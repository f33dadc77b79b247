// The lanes' arithmetic that more than one march uses (cone_lanes_impl.h, shadow_lanes_impl.h),
// for the instruction set VOXGI_LANES_ARCH names (an xsimd arch); VOXGI_LANES_BITS(mask) is the
// instruction that gathers a lane mask's bits. In an unnamed namespace and free of glm and the
// standard library, as those marches' units must be (tests/simd_symbols_test.cmake).
#pragma once

#include <cstdint>

// xsimd (Debian's libxsimd-dev) rather than intrinsics: the lanes stay portable, and its batches
// map one to one onto the IEEE operations of the shared kernels (no contraction, no
// approximations).
#include <xsimd/xsimd.hpp>
#include <immintrin.h>

namespace voxgi::cpu::lane_math {
namespace {

using Arch = VOXGI_LANES_ARCH;
using Lanes = xsimd::batch<float, Arch>;
using LaneInts = xsimd::batch<int32_t, Arch>;
using LaneMask = xsimd::batch_bool<float, Arch>;
constexpr int kWidth = int(Lanes::size);
using LaneBits = uint32_t;  // one bit per lane: at most 32 lanes
// Two batches of lanes: the second's arithmetic overlaps the first's chains and loads.
constexpr int kBatches = 2;
constexpr int kLanes = kBatches * kWidth;
constexpr int kAlign = 64;  // the widest batch's
static_assert(kLanes <= 32);

// Lane j's bit of a mask. (xsimd 8.1's batch_bool has no mask().)
LaneBits bitsOf(LaneMask m) {
  return LaneBits(VOXGI_LANES_BITS(m));
}

// The lanes holding work: job[j] >= 0 (-1: idle).
LaneBits liveLanes(const long (&job)[kLanes]) {
  LaneBits live = 0;
  for (int j = 0; j < kLanes; ++j) live |= LaneBits(job[j] >= 0) << j;
  return live;
}

// floor(x) for |x| < 2^31: the truncation, less 1 where it rounded up (xsimd's floor also handles
// larger magnitudes, which no lane holds).
Lanes floorLanes(Lanes x) {
  const Lanes t = xsimd::to_float(xsimd::to_int(x));
  return t - xsimd::select(t > x, Lanes(1.0f), Lanes(0.0f));
}

}  // namespace
}  // namespace voxgi::cpu::lane_math
