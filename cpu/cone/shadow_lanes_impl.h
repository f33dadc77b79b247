// shadow_lanes.h's march for one instruction set, included once by each of
// shadow_lanes_{sse2,avx2,avx512}.cpp with VOXGI_LANES_ARCH and VOXGI_LANES_BITS(mask)
// (lane_math_impl.h) and VOXGI_SHADOW_LANES_SUFFIX, its entry point's suffix (Sse2:
// marchShadowRaysSse2). Everything else here is in an unnamed namespace and touches no glm or
// standard-library function (tests/simd_symbols_test.cmake checks the wide objects).
#include "cpu/cone/lane_math_impl.h"
#include "cpu/cone/shadow_lanes.h"

namespace voxgi::cpu::shadow_lanes {
namespace {

using namespace lane_math;  // lane_math_impl.h's batches and helpers

// shared::mortonSpread in every lane.
LaneInts spread(LaneInts v) {
  v = v & LaneInts(0x3ff);
  v = (v | (v << 16)) & LaneInts(0x030000ff);
  v = (v | (v << 8)) & LaneInts(0x0300f00f);
  v = (v | (v << 4)) & LaneInts(0x030c30c3);
  v = (v | (v << 2)) & LaneInts(0x09249249);
  return v;
}

// The rays in the lanes, one array per quantity.
struct LaneState {
  alignas(kAlign) float origin[3][kLanes];
  alignas(kAlign) float toLight[3][kLanes];
  alignas(kAlign) float limit[kLanes];
  alignas(kAlign) float t[kLanes];  // the step, a whole number
  alignas(kAlign) float occlusion[kLanes];
  alignas(kAlign) int32_t voxel[3][kLanes];  // this step's voxel
  long ray[kLanes];                          // -1: idle
};

}  // namespace

#define VOXGI_SHADOW_LANES_ENTRY(suffix) marchShadowRays##suffix
#define VOXGI_SHADOW_LANES_NAME(suffix) VOXGI_SHADOW_LANES_ENTRY(suffix)

void VOXGI_SHADOW_LANES_NAME(VOXGI_SHADOW_LANES_SUFFIX)(const ShadowVolume& volume,
                                                        std::span<const ShadowRay> rays,
                                                        std::span<float> visibility) {
  const float n = float(volume.n);
  const float maxSteps = float(volume.maxSteps);
  // Signed and unsigned words may alias; xsimd gathers into signed lanes.
  const int32_t* bits = reinterpret_cast<const int32_t*>(volume.mayBeOpaque);
  LaneState st;
  size_t next = 0;
  const auto start = [&](int j) {
    st.ray[j] = next < rays.size() ? long(next) : -1;
    if (st.ray[j] < 0) return;
    const ShadowRay& r = rays.data()[next++];
    st.origin[0][j] = r.origin.x;
    st.origin[1][j] = r.origin.y;
    st.origin[2][j] = r.origin.z;
    st.toLight[0][j] = r.toLight.x;
    st.toLight[1][j] = r.toLight.y;
    st.toLight[2][j] = r.toLight.z;
    st.limit[j] = r.limit;
    st.t[j] = 0.0f;
    st.occlusion[j] = 0.0f;
  };
  for (int j = 0; j < kLanes; ++j) start(j);

  for (;;) {
    const LaneBits live = liveLanes(st.ray);
    if (live == 0) break;
    // Per batch: the lanes whose march ends before this step's voxel (the step count, the limit,
    // the grid left), and those whose voxel the map marks.
    LaneBits ended = 0, marked = 0;
    for (int o = 0; o < kLanes; o += kWidth) {
      const Lanes t = Lanes::load_aligned(st.t + o);
      LaneMask ends = t >= Lanes(maxSteps) || t >= Lanes::load_aligned(st.limit + o);
      Lanes f[3];
      for (int k = 0; k < 3; ++k) {
        const Lanes q =
            Lanes::load_aligned(st.origin[k] + o) + Lanes::load_aligned(st.toLight[k] + o) * t;
        f[k] = floorLanes(q);
        ends = ends || f[k] < Lanes(0.0f) || f[k] >= Lanes(n);
      }
      LaneInts v[3];
      for (int k = 0; k < 3; ++k) {
        v[k] = xsimd::to_int(xsimd::select(ends, Lanes(0.0f), f[k]));  // in the grid: in the map
        v[k].store_aligned(st.voxel[k] + o);
      }
      const LaneInts key = spread(v[0]) | (spread(v[1]) << 1) | (spread(v[2]) << 2);
      const LaneInts word = LaneInts::gather(bits, key >> 5);
      const LaneInts bit = (word >> (key & LaneInts(31))) & LaneInts(1);
      ended |= bitsOf(ends) << o;
      marked |= bitsOf(xsimd::to_float(bit) > Lanes(0.0f) && !ends) << o;
    }
    ended &= live;
    marked &= live;
    // A marked voxel on its own lane.
    LaneBits blocked = 0;
    for (int j = 0; j < kLanes; ++j) {
      if ((marked >> j & 1) == 0) continue;
      const float occlusion = volume.collide(volume.context, st.voxel[0][j], st.voxel[1][j],
                                             st.voxel[2][j], st.t[j], st.occlusion[j]);
      st.occlusion[j] = occlusion;
      if (occlusion >= 1.0f) blocked |= LaneBits(1) << j;
    }
    for (int o = 0; o < kLanes; o += kWidth)
      (Lanes::load_aligned(st.t + o) + Lanes(1.0f)).store_aligned(st.t + o);
    for (int j = 0; j < kLanes; ++j) {
      if ((blocked >> j & 1) != 0)
        visibility.data()[st.ray[j]] = 0.0f;
      else if ((ended >> j & 1) != 0)
        visibility.data()[st.ray[j]] = 1.0f - st.occlusion[j];
      else
        continue;
      start(j);
    }
  }
}

}  // namespace voxgi::cpu::shadow_lanes
