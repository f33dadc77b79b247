// cone_lanes.h's march for one instruction set, included once by each of
// cone_lanes_{sse2,avx2,avx512}.cpp with VOXGI_LANES_ARCH set to an xsimd arch,
// VOXGI_LANES_BITS(mask) to the instruction that gathers a lane mask's bits (lane_math_impl.h)
// and VOXGI_CONE_LANES_SUFFIX to its entry point's suffix (Sse2: marchConesSse2). Everything else
// here is in an unnamed namespace and touches no glm or standard-library function, so no inline
// function compiled for AVX2 or AVX-512 can stand in for another unit's
// (tests/simd_symbols_test.cmake checks those objects).
#include "cpu/cone/cone_lanes.h"
#include "cpu/cone/lane_math_impl.h"

namespace voxgi::cpu::cone_lanes {
namespace {

// lane_math_impl.h's batches; in the cone march the two batches' polynomial chains (the level's
// log2, the step correction's pow) overlap.
using namespace lane_math;

// One voxel's four words in an SSE register on every level (VEX-encoded where the unit is built
// for AVX): SSE intrinsics are built-ins, so they leave no symbol for another unit to link.
struct Texel {
  __m128 v;
};
Texel texel(float x) {
  return {_mm_set1_ps(x)};
}
Texel operator+(Texel a, Texel b) {
  return {_mm_add_ps(a.v, b.v)};
}
Texel operator-(Texel a, Texel b) {
  return {_mm_sub_ps(a.v, b.v)};
}
Texel operator*(Texel a, Texel b) {
  return {_mm_mul_ps(a.v, b.v)};
}

// glm's min and max, whose choices at ties and signed zeros the shared kernel relies on.
Lanes glmMin(Lanes x, Lanes y) {
  return xsimd::select(y < x, y, x);
}
Lanes glmMax(Lanes x, Lanes y) {
  return xsimd::select(x < y, y, x);
}

// shared::log2Approx for normal x > 0 (a cone's diameter, 1 - opacity): frexp from the exponent
// bits, then the same series.
Lanes log2Lanes(Lanes x) {
  const LaneInts bits = xsimd::bitwise_cast<LaneInts>(x);
  // The exponent as a float: small integers, so e - 1 is exact in either form.
  Lanes e = xsimd::to_float(((bits >> 23) & LaneInts(0xff)) - LaneInts(126));
  Lanes m =
      xsimd::bitwise_cast<Lanes>((bits & LaneInts(int32_t(0x807fffff))) | LaneInts(0x3f000000));
  const LaneMask small = m < Lanes(0.70710678f);
  m = xsimd::select(small, m * Lanes(2.0f), m);
  e = xsimd::select(small, e - Lanes(1.0f), e);
  const Lanes s = (m - Lanes(1.0f)) / (m + Lanes(1.0f));
  const Lanes s2 = s * s;
  const Lanes series =
      s * (Lanes(1.0f) +
           s2 * (Lanes(0.33333333f) +
                 s2 * (Lanes(0.2f) + s2 * (Lanes(0.14285714f) + s2 * Lanes(0.11111111f)))));
  return e + series * Lanes(2.8853901f);
}

// shared::exp2Approx: ldexp(v, i) is v times 2^i exactly for i in [-126, 127].
Lanes exp2Lanes(Lanes x) {
  const Lanes c = glmMin(glmMax(x, Lanes(-126.0f)), Lanes(127.0f));
  const Lanes i = floorLanes(c);
  const Lanes g = (c - i - Lanes(0.5f)) * Lanes(0.69314718f);
  const Lanes p =
      Lanes(1.0f) +
      g * (Lanes(1.0f) +
           g * (Lanes(0.5f) +
                g * (Lanes(0.16666667f) +
                     g * (Lanes(0.041666667f) +
                          g * (Lanes(0.0083333333f) +
                               g * (Lanes(0.0013888889f) + g * Lanes(0.00019841270f)))))));
  const Lanes scale = xsimd::bitwise_cast<Lanes>((xsimd::to_int(i) + LaneInts(127)) << 23);
  return (p * Lanes(1.4142136f)) * scale;
}

// shared::powApprox for x > 0.
Lanes powLanes(Lanes x, Lanes y) {
  return exp2Lanes(y * log2Lanes(x));
}

Texel texelAt(const uint32_t* p) {
  return {_mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))};
}

Texel lerp(Texel a, Texel b, float t) {
  return a + (b - a) * texel(t);
}

// shared::TrilinearCell of one lane, in plain numbers.
struct Cell {
  int base[3];
  float f[3];
  bool inside;
};

// The first words of a trilinear cell's eight voxels in blendCell's order (000, 100, 010, 110,
// 001, 101, 011, 111); null outside the level, whose voxels read as 0 (shared::pyramidVoxel).
struct CellTaps {
  const uint32_t* voxel[8];
};

// The eight voxels of a cell that lies whole in its storage, from its lowest voxel and the words
// to the next voxel along x, y and z.
CellTaps cornerTaps(const uint32_t* lowest, size_t dx, size_t dy, size_t dz) {
  return {{lowest, lowest + dx, lowest + dy, lowest + dx + dy, lowest + dz, lowest + dx + dz,
           lowest + dy + dz, lowest + dx + dy + dz}};
}

CellTaps cellTaps(const Volumes& volumes, int level, const Cell& c, size_t stride) {
  const int size = volumes.n >> level;
  const size_t s = size_t(size);
  const uint32_t* words = volumes.levels[level];
  if (c.inside)
    return cornerTaps(
        words + stride * (size_t(c.base[0]) + s * (size_t(c.base[1]) + s * size_t(c.base[2]))),
        stride, stride * s, stride * s * s);
  CellTaps taps;
  for (int k = 0; k < 8; ++k) {
    const int x = c.base[0] + (k & 1), y = c.base[1] + (k >> 1 & 1), z = c.base[2] + (k >> 2);
    const bool in = x >= 0 && y >= 0 && z >= 0 && x < size && y < size && z < size;
    taps.voxel[k] = in ? words + stride * (size_t(x) + s * (size_t(y) + s * size_t(z))) : nullptr;
  }
  return taps;
}

Texel tapAt(const uint32_t* voxel, size_t face) {
  return voxel != nullptr ? texelAt(voxel + face) : texel(0.0f);
}

// shared::blendCell of one face (its first word `face` words into each voxel). Inlined, so that
// the three faces' loads and lerps interleave (trace_cones 1.12 x faster than a call per face).
[[gnu::always_inline]] inline Texel blendCell(const CellTaps& t, size_t face, const float* f) {
  const Texel y0 = lerp(lerp(tapAt(t.voxel[0], face), tapAt(t.voxel[1], face), f[0]),
                        lerp(tapAt(t.voxel[2], face), tapAt(t.voxel[3], face), f[0]), f[1]);
  const Texel y1 = lerp(lerp(tapAt(t.voxel[4], face), tapAt(t.voxel[5], face), f[0]),
                        lerp(tapAt(t.voxel[6], face), tapAt(t.voxel[7], face), f[0]), f[1]);
  return lerp(y0, y1, f[2]);
}

#ifdef __AVX512F__
// The three faces a cone reads (words 4 face[axis] .. + 3 of a voxel's 24), side by side in one
// AVX-512 register, x's face in words 0-3, y's in 4-7 and z's in 8-11: one lerp blends all three,
// each word as blendCell blends it alone.
struct Faces {
  __m512 v;
};
Faces operator+(Faces a, Faces b) {
  return {_mm512_add_ps(a.v, b.v)};
}
Faces operator-(Faces a, Faces b) {
  return {_mm512_sub_ps(a.v, b.v)};
}
Faces operator*(Faces a, Faces b) {
  return {_mm512_mul_ps(a.v, b.v)};
}
Faces broadcast(float t) {
  return {_mm512_set1_ps(t)};
}
// Where a cone's faces lie in a voxel: the permutation that gathers their words into Faces' order
// from the voxel's words 0-15 and 8-23 (permutex2var's indices 0-15 and 16-31).
struct FacePick {
  __m512i index;
};
FacePick facePick(const int (&face)[3]) {
  alignas(64) int32_t index[16] = {};
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 4; ++k) {
      const int word = 4 * face[axis] + k;
      index[4 * axis + k] = word < 16 ? word : word + 8;
    }
  return {_mm512_load_si512(index)};
}
Faces faceWeights(const float (&w)[3]) {
  return {_mm512_setr_ps(w[0], w[0], w[0], w[0], w[1], w[1], w[1], w[1], w[2], w[2], w[2], w[2],
                         0.0f, 0.0f, 0.0f, 0.0f)};
}
Faces facesAt(const uint32_t* voxel, const FacePick& pick) {
  if (voxel == nullptr) return {_mm512_setzero_ps()};
  const __m512 low = _mm512_castsi512_ps(_mm512_loadu_si512(voxel));
  const __m512 high = _mm512_castsi512_ps(_mm512_loadu_si512(voxel + 8));
  return {_mm512_permutex2var_ps(low, pick.index, high)};
}
// Axis `axis`'s face.
Texel faceOf(Faces f, int axis) {
  return {axis == 0   ? _mm512_extractf32x4_ps(f.v, 0)
          : axis == 1 ? _mm512_extractf32x4_ps(f.v, 1)
                      : _mm512_extractf32x4_ps(f.v, 2)};
}
Faces lerp(Faces a, Faces b, float t) {
  return a + (b - a) * broadcast(t);
}

// blendCell of the cone's three faces at once. Inlined, as brickTaps is: the taps stay in
// registers (the octree's gather 0.29 -> 0.25 s at depth 7; trace_cones unchanged).
[[gnu::always_inline]] inline Faces blendFaces(const CellTaps& t, const FacePick& pick,
                                               const float* f) {
  const Faces y0 = lerp(lerp(facesAt(t.voxel[0], pick), facesAt(t.voxel[1], pick), f[0]),
                        lerp(facesAt(t.voxel[2], pick), facesAt(t.voxel[3], pick), f[0]), f[1]);
  const Faces y1 = lerp(lerp(facesAt(t.voxel[4], pick), facesAt(t.voxel[5], pick), f[0]),
                        lerp(facesAt(t.voxel[6], pick), facesAt(t.voxel[7], pick), f[0]), f[1]);
  return lerp(y0, y1, f[2]);
}
#endif

// What a lane's samples need that stays fixed along its cone: sampleLevel's faces and weights.
struct LaneCone {
  int face[3];
  float weight[3];  // dir^2
#ifdef __AVX512F__
  FacePick pick;  // facePick(face)
  Faces weights;  // faceWeights(weight)
#endif
};

// CellOccupancy::empty, read from its bits.
bool cellEmpty(const Volumes& volumes, int level, const Cell& c) {
  const size_t side = volumes.occupiedSide[level];
  const size_t i =
      size_t(c.base[0] + 1) + side * (size_t(c.base[1] + 1) + side * size_t(c.base[2] + 1));
  return (volumes.occupied[level][i >> 6] >> (i & 63) & 1u) == 0u;
}

// A lane's last tile at each pyramid level of the octree (TreeBricks::findTile), so that a cone's
// next sample in the same tile finds it without walking the tree.
struct TileMemo {
  uint64_t key[16];  // the tile coordinate, packed; kNoTileKey: none yet
  uint32_t tile[16];
};
constexpr uint64_t kNoTileKey = ~uint64_t(0);
constexpr uint32_t kNoTile = 0xffffffffu;  // shared::kSvoNull
constexpr int kBrickSide = 3;              // shared::brickTexel's

// The eight texels of cell c in its tile's brick at pyramid `level` (SvoVolumes::filterBrickCell):
// `stride` words a texel; null for a texel left of the grid, all null without a tile.
[[gnu::always_inline]] inline CellTaps brickTaps(const TreeBricks& bricks, int level, const Cell& c,
                                                 size_t stride, TileMemo& memo) {
  int t[3], o[3];
  for (int k = 0; k < 3; ++k) {
    t[k] = (c.base[k] > 0 ? c.base[k] : 0) >> 1;
    o[k] = c.base[k] - 2 * t[k];
  }
  const uint64_t key = uint64_t(t[0]) | uint64_t(t[1]) << 21 | uint64_t(t[2]) << 42;
  if (memo.key[level] != key) {
    memo.key[level] = key;
    memo.tile[level] =
        bricks.findTile(bricks.tree, level, uint32_t(t[0]), uint32_t(t[1]), uint32_t(t[2]));
  }
  const uint32_t tile = memo.tile[level];
  const uint32_t* brick =
      tile == kNoTile
          ? nullptr
          : bricks.levels[level] + size_t(tile - bricks.firstTile[level]) *
                                       size_t(kBrickSide * kBrickSide * kBrickSide) * stride;
  if (brick != nullptr && o[0] >= 0 && o[1] >= 0 && o[2] >= 0)
    return cornerTaps(brick + stride * size_t(o[0] + kBrickSide * (o[1] + kBrickSide * o[2])),
                      stride, stride * kBrickSide, stride * kBrickSide * kBrickSide);
  CellTaps taps;
  for (int k = 0; k < 8; ++k) {
    const int x = o[0] + (k & 1), y = o[1] + (k >> 1 & 1), z = o[2] + (k >> 2);
    const bool in = brick != nullptr && x >= 0 && y >= 0 && z >= 0;
    taps.voxel[k] = in ? brick + stride * size_t(x + kBrickSide * (y + kBrickSide * z)) : nullptr;
  }
  return taps;
}

// shared::sampleLevel over the trilinear cell c of `level`.
[[gnu::always_inline]] inline Texel sampleLevel(const Volumes& volumes, int level, const Cell& c,
                                                const LaneCone& cone,
                                                const shared::ConeTraceParams& params,
                                                TileMemo& memo) {
  const bool directional = level > 0 && params.directional != 0;
  CellTaps taps;
  // Words from one voxel (texel) to the next.
  const int stride = volumes.bricks != nullptr ? 4 * volumes.bricks->faces[level]
                     : directional             ? 4 * volumes.faces
                                               : 4;
  if (volumes.bricks != nullptr) {
    // A cell without a tile reads eight zero texels, which blend to +0 on every face. (Its last
    // texel, base + 1 on each axis, is never left of the grid: null only without a tile.)
    taps = brickTaps(*volumes.bricks, level, c, size_t(stride), memo);
    if (taps.voxel[7] == nullptr) return texel(0.0f);
  } else {
    if (cellEmpty(volumes, level, c)) return texel(0.0f);
    taps = cellTaps(volumes, level, c, size_t(stride));
  }
  if (!directional) return blendCell(taps, 0, c.f);
#ifdef __AVX512F__
  if (stride == 24) {
    // Each face weighted as below, then summed in the same order.
    const Faces weighted = blendFaces(taps, cone.pick, c.f) * cone.weights;
    Texel sum = texel(0.0f);
    for (int axis = 0; axis < 3; ++axis)
      if (cone.weight[axis] > 0.0f) sum = sum + faceOf(weighted, axis);
    return sum;
  }
#endif
  Texel sum = texel(0.0f);
  for (int axis = 0; axis < 3; ++axis)
    if (cone.weight[axis] > 0.0f)
      sum = sum + blendCell(taps, 4 * size_t(cone.face[axis]), c.f) * texel(cone.weight[axis]);
  return sum;
}

// shared::trilinearCell of `level` for every lane: 1 / 2^level from the exponent bits (exact, as
// the kernel's 1 / float(1 << level) is), then the same operations.
struct LaneCells {
  alignas(kAlign) int32_t base[3][kLanes];
  alignas(kAlign) float f[3][kLanes];
  LaneBits inside = 0;

  // Lanes o .. o + kWidth - 1.
  void fill(int o, const Lanes (&q)[3], Lanes level, float n) {
    const LaneInts l = xsimd::to_int(level);
    const Lanes scale = xsimd::bitwise_cast<Lanes>((LaneInts(127) - l) << 23);
    // The level has n / 2^level voxels a side, rounded down: lowest + 1 < that whole number
    // exactly where lowest + 2 <= n / 2^level.
    const Lanes size = Lanes(n) * scale;
    LaneMask in(true);
    for (int k = 0; k < 3; ++k) {
      const Lanes c = q[k] * scale - Lanes(0.5f);
      const Lanes lowest = floorLanes(c);
      (c - lowest).store_aligned(f[k] + o);
      xsimd::to_int(lowest).store_aligned(base[k] + o);
      in = in && lowest >= Lanes(0.0f) && lowest + Lanes(2.0f) <= size;
    }
    inside |= bitsOf(in) << o;
  }
  Cell at(int j) const {
    return {
        {base[0][j], base[1][j], base[2][j]}, {f[0][j], f[1][j], f[2][j]}, (inside >> j & 1) != 0};
  }
};

// The cones in the lanes, one array per quantity.
struct LaneState {
  alignas(kAlign) float origin[3][kLanes];
  alignas(kAlign) float direction[3][kLanes];
  alignas(kAlign) float rise[kLanes], tanHalf[kLanes], maxDistance[kLanes];
  alignas(kAlign) float t[kLanes], occlusion[kLanes], radiance[3][kLanes], ambient[kLanes];
  alignas(kAlign) float sample[4][kLanes];  // this step's samples
  alignas(kAlign) float steps[kLanes];      // steps taken (exact integers)
  long job[kLanes];                         // -1: idle
  LaneCone cone[kLanes];
  TileMemo memo[kLanes];  // kept from cone to cone: a lane's next cone starts nearby
};

// A vector's components by index, without glm's operator[].
float component(const glm::vec3& v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

// Where each lane's cone samples this step, found per batch before sampling: the lanes that stop
// here (the step limit or the distance reached: `over`; the grid left: `exited`), each lane's
// diameter, lower level and the fraction towards the next, and its trilinear cells in both levels.
struct StepPlan {
  LaneBits over = 0, exited = 0;
  alignas(kAlign) float diameters[kLanes], l0s[kLanes], fs[kLanes];
  LaneCells lower, upper;
};

// One march of `jobs` (cone_lanes.h, marchCones): each lane takes the next job when its cone ends,
// until every job is done. A step is three passes over the lanes: plan (per batch), sample (per
// lane: a quadrilinear sample through the volumes' cells), composite (per batch).
class LaneMarch {
 public:
  LaneMarch(const Volumes& volumes, std::span<const ConeJob> jobs, int kind,
            const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits)
      : volumes_(volumes),
        jobs_(jobs),
        kind_(kind),
        params_(params),
        hits_(hits),
        n_(float(params.resolution)),
        beta_(params.coneStep),
        ambient_(params.ambientOcclusion == 1 && kind <= shared::kMarchFirstHit),
        radiance_(kind <= shared::kMarchFirstHit) {
    for (TileMemo& m : st_.memo)
      for (uint64_t& key : m.key) key = kNoTileKey;
  }

  void run() {
    for (int j = 0; j < kLanes; ++j) start(j);
    for (;;) {
      const LaneBits live = liveLanes(st_.job);
      if (live == 0) break;
      StepPlan plan;
      planStep(live, plan);
      sample(live & ~plan.over & ~plan.exited, plan);
      const LaneBits ended = composite(plan);
      for (int j = 0; j < kLanes; ++j) {
        if (ended >> j & 1)
          finish(j, false);
        else if (plan.exited >> j & 1)
          finish(j, true);
      }
    }
  }

 private:
  // Lane j takes the next job, or goes idle when none is left.
  void start(int j) {
    st_.job[j] = next_ < jobs_.size() ? long(next_) : -1;
    if (st_.job[j] < 0) return;
    const ConeJob& c = jobs_.data()[next_++];
    for (int k = 0; k < 3; ++k) {
      st_.origin[k][j] = component(c.origin, k);
      st_.direction[k][j] = component(c.direction, k);
      st_.radiance[k][j] = 0.0f;
    }
    st_.rise[j] = c.rise;
    st_.tanHalf[j] = c.tanHalf;
    st_.maxDistance[j] = c.maxDistance;
    st_.t[j] = 0.5f;
    st_.occlusion[j] = 0.0f;
    st_.ambient[j] = 0.0f;
    st_.steps[j] = 0.0f;
    const glm::vec3& d = c.direction;
    LaneCone& cone = st_.cone[j];
    cone.face[0] = d.x >= 0.0f ? 0 : 1;
    cone.face[1] = d.y >= 0.0f ? 2 : 3;
    cone.face[2] = d.z >= 0.0f ? 4 : 5;
    cone.weight[0] = d.x * d.x;
    cone.weight[1] = d.y * d.y;
    cone.weight[2] = d.z * d.z;
#ifdef __AVX512F__
    cone.pick = facePick(cone.face);
    cone.weights = faceWeights(cone.weight);
#endif
  }

  // Lane j's cone ends (`exited`: it left the grid, and sees the background through what it did
  // not occlude): its hit, then the lane's next job.
  void finish(int j, bool exited) {
    shared::ConeHit& h = hits_.data()[st_.job[j]];
    h.radiance.x = st_.radiance[0][j];
    h.radiance.y = st_.radiance[1][j];
    h.radiance.z = st_.radiance[2][j];
    h.occlusion = st_.occlusion[j];
    h.ambient = st_.ambient[j];
    if (exited && radiance_) {
      // glm's vec3(background) * (1 - occlusion) + radiance, component by component.
      const float open = 1.0f - h.occlusion;
      h.radiance.x = h.radiance.x + params_.background.x * open;
      h.radiance.y = h.radiance.y + params_.background.y * open;
      h.radiance.z = h.radiance.z + params_.background.z * open;
    }
    start(j);
  }

  void planStep(LaneBits live, StepPlan& p) const {
    for (int o = 0; o < kLanes; o += kWidth) {
      const Lanes t = Lanes::load_aligned(st_.t + o);
      const LaneBits stop =
          bitsOf(t > Lanes::load_aligned(st_.maxDistance + o) ||
                 Lanes::load_aligned(st_.steps + o) >= Lanes(float(params_.maxSteps)));
      Lanes q[3];
      LaneMask outside(false);
      for (int k = 0; k < 3; ++k) {
        q[k] =
            Lanes::load_aligned(st_.origin[k] + o) + Lanes::load_aligned(st_.direction[k] + o) * t;
        outside = outside || q[k] < Lanes(0.0f) || q[k] > Lanes(n_);
      }
      p.over |= stop << o;
      p.exited |= (bitsOf(outside) & ~stop) << o;
      Lanes width = Lanes(2.0f) * t * Lanes::load_aligned(st_.tanHalf + o);
      if (params_.coneClearance > 0.0f) {
        const Lanes height = Lanes(params_.coneOffset) + t * Lanes::load_aligned(st_.rise + o);
        width = glmMin(width, height * Lanes(params_.coneClearance));
      }
      const Lanes diameter = glmMax(width, Lanes(1.0f));
      const Lanes level = glmMin(log2Lanes(diameter), Lanes(float(params_.topLevel)));
      const Lanes l0 = floorLanes(level);
      diameter.store_aligned(p.diameters + o);
      l0.store_aligned(p.l0s + o);
      (level - l0).store_aligned(p.fs + o);
      p.lower.fill(o, q, l0, n_);
      p.upper.fill(o, q, l0 + Lanes(1.0f), n_);
    }
    p.over &= live;
    p.exited &= live;
  }

  // Each sampling lane's quadrilinear sample (shared::sampleCone), filtered on its own; the
  // others sample 0.
  void sample(LaneBits sampling, const StepPlan& p) {
    for (int j = 0; j < kLanes; ++j) {
      Texel s = texel(0.0f);
      if (sampling >> j & 1) {
        const int l = int(p.l0s[j]);
        s = sampleLevel(volumes_, l, p.lower.at(j), st_.cone[j], params_, st_.memo[j]);
        if (p.fs[j] != 0.0f)
          s = lerp(s,
                   sampleLevel(volumes_, l + 1, p.upper.at(j), st_.cone[j], params_, st_.memo[j]),
                   p.fs[j]);
      }
      alignas(16) float v[4];  // one texel
      _mm_store_ps(v, s.v);
      for (int k = 0; k < 4; ++k) st_.sample[k][j] = v[k];
    }
  }

  // The sample's opacity corrected for the step (shared::marchCone's), per kind of march.
  Lanes correctedOpacity(Lanes a, LaneMask seen, Lanes t, int o) const {
    if (kind_ == shared::kMarchShadowKahl) {
      const Lanes x =
          xsimd::sqrt(t) * Lanes(params_.shadowStrength) / Lanes::load_aligned(st_.maxDistance + o);
      const Lanes c = glmMin(glmMax(x, Lanes(0.0f)), Lanes(1.0f));
      return a * (c * c * (Lanes(3.0f) - Lanes(2.0f) * c));
    }
    if (beta_ == 1.0f) return a;
    const LaneMask opaque = a >= Lanes(1.0f);
    const Lanes transparency = xsimd::select(seen && !opaque, Lanes(1.0f) - a, Lanes(1.0f));
    return xsimd::select(opaque, a, Lanes(1.0f) - powLanes(transparency, Lanes(beta_)));
  }

  // Per batch after sampling: the step correction, compositing front to back and the next step;
  // returns the lanes whose cones ended (over, a first hit, or opaque).
  LaneBits composite(const StepPlan& p) {
    LaneBits ended = p.over;
    for (int o = 0; o < kLanes; o += kWidth) {
      const Lanes t = Lanes::load_aligned(st_.t + o);
      const Lanes diameter = Lanes::load_aligned(p.diameters + o);
      const Lanes sampleAlpha = Lanes::load_aligned(st_.sample[3] + o);
      const Lanes a = glmMin(sampleAlpha, Lanes(1.0f));
      LaneMask seen = a > Lanes(0.0f);  // lanes that did not sample hold 0
      // Empty space (about half the samples): nothing to composite, the cones only step on.
      if (xsimd::any(seen)) {
        const Lanes corrected = correctedOpacity(a, seen, t, o);
        if (kind_ == shared::kMarchFirstHit) {
          // [Kahl 2019, §5.4.4]: the first sample past 1/100 is the surface, and the cone ends.
          const LaneMask hit = seen && corrected > Lanes(0.01f);
          ended |= bitsOf(hit) << o;
          seen = seen && !hit;
          for (int k = 0; k < 3; ++k) {
            const Lanes surface = Lanes::load_aligned(st_.sample[k] + o) / sampleAlpha;
            xsimd::select(hit, surface, Lanes::load_aligned(st_.radiance[k] + o))
                .store_aligned(st_.radiance[k] + o);
          }
          xsimd::select(hit, Lanes(1.0f), Lanes::load_aligned(st_.occlusion + o))
              .store_aligned(st_.occlusion + o);
        }
        ended |= accumulate(seen, a, corrected, diameter, o);
      }
      (t + glmMax(Lanes(beta_) * diameter, Lanes(params_.minStep))).store_aligned(st_.t + o);
      (Lanes::load_aligned(st_.steps + o) + Lanes(1.0f)).store_aligned(st_.steps + o);
    }
    return ended;
  }

  // The seen lanes' radiance, ambient occlusion and occlusion with this step's sample; returns
  // those now opaque.
  LaneBits accumulate(LaneMask seen, Lanes a, Lanes corrected, Lanes diameter, int o) {
    const Lanes occlusion = Lanes::load_aligned(st_.occlusion + o);
    const Lanes remaining = Lanes(1.0f) - occlusion;
    if (radiance_) {
      const Lanes scale = remaining * corrected / a;
      for (int k = 0; k < 3; ++k) {
        const Lanes r = Lanes::load_aligned(st_.radiance[k] + o);
        xsimd::select(seen, r + Lanes::load_aligned(st_.sample[k] + o) * scale, r)
            .store_aligned(st_.radiance[k] + o);
      }
    }
    if (ambient_) {
      const Lanes falloff =
          Lanes(1.0f) / (Lanes(1.0f) + Lanes(params_.ambientLambda) * (Lanes(0.5f) * diameter));
      const Lanes before = Lanes::load_aligned(st_.ambient + o);
      xsimd::select(seen, before + (Lanes(1.0f) - before) * corrected * falloff, before)
          .store_aligned(st_.ambient + o);
    }
    const Lanes occluded = xsimd::select(seen, occlusion + remaining * corrected, occlusion);
    occluded.store_aligned(st_.occlusion + o);
    return bitsOf(seen && occluded >= Lanes(0.999f)) << o;
  }

  const Volumes& volumes_;
  std::span<const ConeJob> jobs_;
  int kind_;
  const shared::ConeTraceParams& params_;
  std::span<shared::ConeHit> hits_;
  float n_, beta_;
  bool ambient_, radiance_;
  size_t next_ = 0;  // the next job a lane takes
  LaneState st_;
};

}  // namespace

#define VOXGI_CONE_LANES_ENTRY(suffix) marchCones##suffix
#define VOXGI_CONE_LANES_NAME(suffix) VOXGI_CONE_LANES_ENTRY(suffix)

void VOXGI_CONE_LANES_NAME(VOXGI_CONE_LANES_SUFFIX)(const Volumes& volumes,
                                                    std::span<const ConeJob> jobs, int kind,
                                                    const shared::ConeTraceParams& params,
                                                    std::span<shared::ConeHit> hits) {
  LaneMarch(volumes, jobs, kind, params, hits).run();
}

}  // namespace voxgi::cpu::cone_lanes
