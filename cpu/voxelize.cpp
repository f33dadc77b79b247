// CPU voxelize stage: every (triangle, voxel) pair the shared kernel accepts is accumulated with
// integer atomics (order-independent, so bit-identical for any thread count), then resolved. A
// fresh voxelization accumulates into the blocks of 8^3 voxels the surface reaches (BlockSums) and
// resolves those blocks alone: every other voxel resolves to the zeros its buffers start with. The
// dense sums are outputs only where the plan keeps them (Effect::voxel_sums), filled from the
// blocks. In a sequence where a few meshes moved, the frame before's dense sums are updated in
// part instead ([Villegas 2017, §1.2] revoxelizes its dynamic objects alone): the moved meshes'
// contributions of that frame are subtracted, this frame's added, and only the blocks of 8^3
// voxels either touched are resolved again. Integer sums make the update exact, so the buffers are
// the ones voxelizing every triangle gives.
#include <algorithm>
#include <atomic>
#include <bit>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/memory.h"
#include "common/parallel.h"
#include "common/voxel_overflow.h"
#include "common/voxelize_update.h"
#include "common/voxel_walk.h"
#include "cpu/stages.h"

namespace voxgi::cpu {
namespace {

using shared::VoxelContribution;
using shared::VoxelTriangle;

// A voxel's sums on adjacent words: weight, albedo (3), normal (3), then with emission its rgb and
// the emitters' weight.
constexpr int kSumWords = 7, kEmissiveSumWords = 11;

// Adds (or, subtracting, takes out) one contribution into a voxel's sums, wherever they lie:
// `word(i)` is the voxel's i-th sum word. Returns the weight sum before the addition.
template <class Word>
uint32_t addContribution(const shared::VoxelContribution& c, bool emissive, bool subtract,
                         Word&& word) {
  const auto add = [&](int i, uint32_t v) {
    // Adding (0 - v) modulo 2^32 takes v out exactly.
    return std::atomic_ref<uint32_t>(word(i)).fetch_add(subtract ? 0u - v : v,
                                                        std::memory_order_relaxed);
  };
  const uint32_t old = add(0, c.weight);
  for (int i = 0; i < 3; ++i) {
    add(1 + i, c.albedo[i]);
    add(4 + i, static_cast<uint32_t>(c.normal[i]));
    if (emissive) add(7 + i, c.emission[i]);
  }
  if (emissive) add(10, c.emitterWeight);
  return old;
}

// Set by the first contribution that takes a voxel past kMaxWeightSum: the sums of that voxel are
// lost, the stage fails, so the remaining triangles are skipped.
struct Overflow {
  std::atomic<bool> flag{false};
  // Adds alone raise a sum, so the check fires exactly when the final sum passes the bound.
  void check(uint32_t old, uint32_t weight) {
    if (uint64_t(old) + weight > shared::kMaxWeightSum) flag.store(true, std::memory_order_relaxed);
  }
};

// A fresh voxelization's sums, held only in the blocks of 8^3 voxels the surface reaches (a small
// mesh's surface touches few of a grid's blocks), a voxel's sums on adjacent words: the dense sums
// cost clearing and writing 28-44 bytes a voxel of the whole grid, where the blocks' cost what the
// surface covers. A first walk marks the blocks, which take their places in index order; the
// second adds the contributions.
struct BlockSums {
  static constexpr int kShift = 3, kVoxels = 1 << (3 * kShift);
  int side, words;
  std::vector<uint32_t> place;  // per block of the grid: 1 + its index in `low`, or 0
  std::vector<glm::ivec3> low;  // the marked blocks' lowest voxels, in index order, once listed
  Words sums;

  BlockSums(int n, bool emissive)
      : side(((n - 1) >> kShift) + 1),
        words(emissive ? kEmissiveSumWords : kSumWords),
        place(size_t(side) * size_t(side) * size_t(side), 0) {}
  size_t blockIndex(const glm::ivec3& voxel) const {
    const glm::ivec3 b = voxel >> kShift;
    return size_t(b.x) + size_t(side) * (size_t(b.y) + size_t(side) * size_t(b.z));
  }
  void mark(size_t block) {
    // A racing store of the same 1 is harmless; the atomic keeps ThreadSanitizer informed.
    std::atomic_ref<uint32_t>(place[block]).store(1, std::memory_order_relaxed);
  }
  bool marked(const glm::ivec3& voxel) const { return place[blockIndex(voxel)] != 0; }
  // The marked blocks' lowest voxels, in index order.
  std::vector<glm::ivec3> markedList() const {
    std::vector<glm::ivec3> out;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
          if (marked(glm::ivec3(x, y, z) << kShift)) out.push_back(glm::ivec3(x, y, z) << kShift);
    return out;
  }
  // Gives the marked blocks their places; refuses, before allocating, sums that memory cannot hold.
  void allocate(const StageContext& ctx) {
    low = markedList();
    for (size_t b = 0; b < low.size(); ++b) place[blockIndex(low[b])] = uint32_t(b + 1);
    const uint64_t count = uint64_t(low.size()) * kVoxels * uint64_t(words);
    requireMemory(count * sizeof(uint32_t),
                  "the voxelize sums of " + std::to_string(low.size()) + " blocks of 8^3 voxels",
                  ctx.scene.file, "grid.resolution");
    sums.resize(count);
  }
  // The first sum word of a voxel in a marked block.
  uint32_t* at(const glm::ivec3& voxel) {
    const size_t local = size_t(voxel.x & 7) | size_t(voxel.y & 7) << 3 | size_t(voxel.z & 7) << 6;
    return &sums[((place[blockIndex(voxel)] - 1) * size_t(kVoxels) + local) * size_t(words)];
  }
};

// Adds contributions into the dense sums (the frame before's, updated in part), marking the
// blocks they reach.
struct DenseAccumulator {
  const GridSpec& grid;
  Buffer& weight;
  Buffer& albedo;
  Buffer& normal;
  Buffer* emission;  // null when the scene emits nothing
  BlockSums& touched;
  Overflow& overflow;
  bool subtract = false;

  void operator()(const glm::ivec3& voxel, const VoxelContribution& c) {
    const size_t e = grid.index(voxel);
    touched.mark(touched.blockIndex(voxel));
    const uint32_t old = addContribution(c, emission != nullptr, subtract, [&](int i) -> uint32_t& {
      if (i == 0) return weight.words[e];
      if (i < 4) return albedo.words[3 * e + size_t(i - 1)];
      if (i < 7) return normal.words[3 * e + size_t(i - 4)];
      return emission->words[4 * e + size_t(i - 7)];
    });
    if (!subtract) overflow.check(old, c.weight);
  }
};

// Whether a voxel that no contribution reached resolves to +0 in every output (all of its sums 0),
// the bits a fresh buffer holds: so for a scale that is not negative or NaN.
bool resolvesToZero(bool antialiased, bool emissive, float emissionScale) {
  const auto zero = [](float x) { return std::bit_cast<uint32_t>(x) == 0u; };
  const glm::vec3 blank = shared::resolveAverage(glm::uvec3(0u), 0u);
  const glm::vec3 normal = shared::resolveNormal(glm::ivec3(0), 0u);
  const glm::vec3 emission = shared::resolveEmission(glm::uvec3(0u), 0u, emissionScale);
  bool all = zero(shared::resolveOpacity(0u, antialiased));
  for (int c = 0; c < 3; ++c)
    all = all && zero(blank[c]) && zero(normal[c]) && (!emissive || zero(emission[c]));
  return all;
}

// The sums and resolved volumes of the stage, allocated or taken from the frame before.
struct VoxelBuffers {
  Buffer weight, albedoSum, normalSum, emissionSum, opacity, albedo, normal, emission;
};

}  // namespace

void common::voxelize(const StageContext& ctx, BufferSet& buffers) {
  const GridSpec& grid = ctx.scene.grid;
  const int n = grid.resolution;
  checkStageMemory(ctx, StageId::common_voxelize);
  refuseRepeatedTriangles(ctx.triangles, n, ctx.settings.voxelizeMode == VoxelizeMode::antialiased,
                          ctx.scene.file);
  const bool antialiased = ctx.settings.voxelizeMode == VoxelizeMode::antialiased;
  const bool emissive =
      ctx.plan.on(Effect::emission);  // emissionScale may be 0 under plan.mode=full
  const bool emitterMean = ctx.settings.voxelizeEmission == VoxelizeEmission::emitters;
  // The dense sums are outputs only where the plan keeps them (voxel_sums): compared, written, read
  // by a later stage or updated in part in the next frame. Otherwise the sums live in BlockSums.
  const bool keepSums = ctx.plan.on(Effect::voxel_sums);
  const glm::ivec3 extent(n);
  // The update starts from the frame before's dense sums, which the stash holds only when the plan
  // kept them.
  const std::optional<MovedTriangles> moved = movedTriangles(ctx, emissive);
  VoxelBuffers v;
  if (moved) {
    BufferSet& stash = ctx.previous->stash;
    v = {stash.take(BufferId::common_voxelize_weight_sum),
         stash.take(BufferId::common_voxelize_albedo_sum),
         stash.take(BufferId::common_voxelize_normal_sum),
         stash.take(BufferId::common_voxelize_emission_sum),
         stash.take(BufferId::common_voxelize_opacity),
         stash.take(BufferId::common_voxelize_albedo),
         stash.take(BufferId::common_voxelize_normal),
         stash.take(BufferId::common_voxelize_emission)};
  } else {
    const auto fresh = [&](BufferId id, bool needed) {
      return needed ? Buffer(id, extent) : Buffer();
    };
    v = {fresh(BufferId::common_voxelize_weight_sum, keepSums),
         fresh(BufferId::common_voxelize_albedo_sum, keepSums),
         fresh(BufferId::common_voxelize_normal_sum, keepSums),
         fresh(BufferId::common_voxelize_emission_sum, keepSums && emissive),
         fresh(BufferId::common_voxelize_opacity, true),
         fresh(BufferId::common_voxelize_albedo, true),
         fresh(BufferId::common_voxelize_normal, true),
         fresh(BufferId::common_voxelize_emission, emissive)};
  }

  BlockSums blocks(n, emissive);
  Overflow overflow;
  const TextureAccess textures{ctx.scene.textures};
  const auto walk = [&](const std::vector<shared::VoxelTriangle>& tris, size_t first, size_t end,
                        auto& sink) {
    parallelFor(tbb::blocked_range<size_t>(first, end, 64), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        // A million copies of one triangle fail after the first few thousand, not after all.
        if (overflow.flag.load(std::memory_order_relaxed)) return;
        if (antialiased)
          antialiasedWalk(tris[i], n, textures, sink);
        else
          conservativeWalk(tris[i], n, textures, sink);
      }
    });
  };
  if (moved) {
    DenseAccumulator acc{
        grid,   v.weight, v.albedoSum, v.normalSum, emissive ? &v.emissionSum : nullptr,
        blocks, overflow};
    // Every subtraction before any addition, so that a running sum passes the bound only when
    // the final one does.
    acc.subtract = true;
    for (const auto& [first, end] : moved->before)
      walk(ctx.previous->triangles->triangles, first, end, acc);
    acc.subtract = false;
    for (const auto& [first, end] : moved->now) walk(ctx.triangles.triangles, first, end, acc);
    blocks.low = blocks.markedList();  // resolved again; the sums stay dense
  } else {
    const std::vector<shared::VoxelTriangle>& tris = ctx.triangles.triangles;
    // The blocks of the walks' candidate voxels, a superset of those contributions reach (a block
    // marked in vain resolves to the zeros it holds) at a fraction of the contributions' cost: each
    // block is marked once per run of a triangle's candidates in it.
    parallelFor(tbb::blocked_range<size_t>(0, tris.size(), 64), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        size_t last = SIZE_MAX;
        const auto mark = [&](const glm::ivec3& voxel) {
          const size_t b = blocks.blockIndex(voxel);
          if (b != last) blocks.mark(b);
          last = b;
        };
        if (antialiased)
          antialiasedCandidates(tris[i], n, mark);
        else
          conservativeCandidates(tris[i], n, mark);
      }
    });
    blocks.allocate(ctx);
    auto add = [&](const glm::ivec3& voxel, const VoxelContribution& c) {
      uint32_t* sums = blocks.at(voxel);
      overflow.check(
          addContribution(c, emissive, false, [sums](int i) -> uint32_t& { return sums[i]; }),
          c.weight);
    };
    walk(tris, 0, tris.size(), add);
  }

  if (overflow.flag)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");

  // Voxel e's outputs from its sums (kSumWords or kEmissiveSumWords words, BlockSums' order).
  const auto resolve = [&](size_t e, const uint32_t* s) {
    const uint32_t w = s[0];
    v.opacity.set(e, 0, shared::resolveOpacity(w, antialiased));
    const glm::vec3 a = shared::resolveAverage(glm::uvec3(s[1], s[2], s[3]), w);
    const glm::vec3 nm = shared::resolveNormal(glm::ivec3(glm::uvec3(s[4], s[5], s[6])), w);
    for (int c = 0; c < 3; ++c) {
      v.albedo.set(e, c, a[c]);
      v.normal.set(e, c, nm[c]);
    }
    if (emissive) {
      const glm::vec3 em = shared::resolveEmission(
          glm::uvec3(s[7], s[8], s[9]), emitterMean ? s[10] : w, ctx.triangles.emissionScale);
      for (int c = 0; c < 3; ++c) v.emission.set(e, c, em[c]);
    }
  };
  // The dense sums of voxel e, gathered into BlockSums' order or scattered from it.
  const auto denseSums = [&](size_t e, auto&& visit) {
    visit(v.weight.words[e], 0);
    for (int c = 0; c < 3; ++c) {
      visit(v.albedoSum.words[3 * e + size_t(c)], 1 + c);
      visit(v.normalSum.words[3 * e + size_t(c)], 4 + c);
    }
    if (emissive)
      for (int c = 0; c < 4; ++c) visit(v.emissionSum.words[4 * e + size_t(c)], 7 + c);
  };
  // Whether a voxel without sums resolves to the +0 that fresh buffers hold.
  const bool blank = resolvesToZero(antialiased, emissive, ctx.triangles.emissionScale);
  const auto resolveVoxel = [&](const glm::ivec3& voxel) {
    const size_t e = grid.index(voxel);
    if (moved) {
      uint32_t s[kEmissiveSumWords] = {};
      denseSums(e, [&](uint32_t word, int i) { s[i] = word; });
      return resolve(e, s);
    }
    static constexpr uint32_t kZero[kEmissiveSumWords] = {};
    const uint32_t* s = blocks.marked(voxel) ? blocks.at(voxel) : kZero;
    // Most voxels of a block the surface reaches are empty, and hold what they resolve to.
    if (blank && std::all_of(s, s + blocks.words, [](uint32_t w) { return w == 0u; })) return;
    resolve(e, s);
    if (keepSums) denseSums(e, [&](uint32_t& word, int i) { word = s[i]; });
  };
  // Only the blocks contributions reached are resolved where every other voxel already holds its
  // value: the frame before's outputs (a voxel resolves from its sums alone, and the update leaves
  // the others' sums as they were), or fresh buffers' +0 where that is what a voxel without
  // contributions resolves to (resolvesToZero). Each block by one task, its voxels in index order.
  if (moved || blank) {
    const std::vector<glm::ivec3>& low = blocks.low;
    const int side = 1 << BlockSums::kShift;
    parallelFor(tbb::blocked_range<size_t>(0, low.size(), 8), [&](const auto& range) {
      for (size_t b = range.begin(); b != range.end(); ++b) {
        const glm::ivec3 high = glm::min(low[b] + side, glm::ivec3(n));
        for (int z = low[b].z; z < high.z; ++z)
          for (int y = low[b].y; y < high.y; ++y)
            for (int x = low[b].x; x < high.x; ++x) resolveVoxel({x, y, z});
      }
    });
  } else {
    parallelFor(tbb::blocked_range<size_t>(0, size_t(n) * size_t(n) * size_t(n), 4096),
                [&](const auto& range) {
                  for (size_t e = range.begin(); e != range.end(); ++e)
                    resolveVoxel(glm::ivec3(int(e % size_t(n)), int(e / size_t(n) % size_t(n)),
                                            int(e / (size_t(n) * size_t(n)))));
                });
  }
  for (Buffer* b : {&v.weight, &v.albedoSum, &v.normalSum, &v.emissionSum, &v.opacity, &v.albedo,
                    &v.normal, &v.emission})
    if (b->spec != nullptr) buffers.put(std::move(*b));
}

}  // namespace voxgi::cpu
