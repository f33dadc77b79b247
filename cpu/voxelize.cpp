// CPU voxelize stage: every (triangle, voxel) pair the shared kernel accepts is accumulated with
// integer atomics (order-independent, so bit-identical for any thread count), then resolved. In a
// sequence where a few meshes moved, the frame before's sums are updated in part instead
// ([Villegas 2017, §1.2] revoxelizes its dynamic objects alone): the moved meshes' contributions of
// that frame are subtracted, this frame's added, and only the blocks of 8^3 voxels either touched
// are resolved again. Integer sums make the update exact, so the buffers are the ones voxelizing
// every triangle gives. A fresh voxelization resolves only the blocks contributions reached too:
// the rest resolve to the zeros the buffers start with.
#include <atomic>
#include <bit>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/parallel.h"
#include "common/voxel_overflow.h"
#include "common/voxelize_update.h"
#include "common/voxel_walk.h"
#include "cpu/stages.h"

namespace voxgi::cpu {
namespace {

using shared::VoxelContribution;
using shared::VoxelTriangle;

// Which blocks of 8^3 voxels any contribution reached: a small mesh's surface touches few, and
// only those are resolved (the other voxels keep the zeros their buffers were allocated with).
struct TouchedBlocks {
  static constexpr int kShift = 3;
  int side;  // blocks a side
  std::vector<uint8_t> marks;

  explicit TouchedBlocks(int n)
      : side(((n - 1) >> kShift) + 1), marks(size_t(side) * size_t(side) * size_t(side), 0) {}
  void mark(const glm::ivec3& voxel) {
    const glm::ivec3 b = voxel >> kShift;
    const size_t i = size_t(b.x) + size_t(side) * (size_t(b.y) + size_t(side) * size_t(b.z));
    // A racing store of the same 1 is harmless; the atomic keeps ThreadSanitizer informed.
    std::atomic_ref<uint8_t>(marks[i]).store(1, std::memory_order_relaxed);
  }
  // The marked blocks' lowest voxels, in index order.
  std::vector<glm::ivec3> list() const {
    std::vector<glm::ivec3> out;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
          if (marks[size_t(x) + size_t(side) * (size_t(y) + size_t(side) * size_t(z))] != 0)
            out.push_back(glm::ivec3(x, y, z) << kShift);
    return out;
  }
};

struct Accumulator {
  const GridSpec& grid;
  Buffer& weight;
  Buffer& albedo;
  Buffer& normal;
  Buffer* emission;       // null when the scene emits nothing
  bool subtract = false;  // take the contributions out (wrapping, exact) instead of adding
  TouchedBlocks* touched = nullptr;  // when set, the blocks a contribution reaches
  // Set by the first contribution that takes a voxel past kMaxWeightSum: the sums of that voxel
  // are lost, the stage fails, so the remaining triangles are skipped.
  std::atomic<bool> overflow{false};

  static void add(uint32_t& word, uint32_t value) {
    std::atomic_ref<uint32_t>(word).fetch_add(value, std::memory_order_relaxed);
  }

  void operator()(const glm::ivec3& voxel, const VoxelContribution& c) {
    const size_t e = grid.index(voxel);
    if (touched != nullptr) touched->mark(voxel);
    // Adding (0 - v) modulo 2^32 takes v out exactly.
    const auto term = [this](uint32_t v) { return subtract ? 0u - v : v; };
    const uint32_t old = std::atomic_ref<uint32_t>(weight.words[e])
                             .fetch_add(term(c.weight), std::memory_order_relaxed);
    // Adds alone raise a sum, so the check fires exactly when the final sum passes the bound.
    if (!subtract && uint64_t(old) + c.weight > shared::kMaxWeightSum)
      overflow.store(true, std::memory_order_relaxed);
    for (int i = 0; i < 3; ++i) {
      add(albedo.words[3 * e + size_t(i)], term(c.albedo[i]));
      add(normal.words[3 * e + size_t(i)], term(static_cast<uint32_t>(c.normal[i])));
      if (emission != nullptr) add(emission->words[4 * e + size_t(i)], term(c.emission[i]));
    }
    if (emission != nullptr) add(emission->words[4 * e + 3], term(c.emitterWeight));
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
  const glm::ivec3 extent(n);
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
    v = {Buffer(BufferId::common_voxelize_weight_sum, extent),
         Buffer(BufferId::common_voxelize_albedo_sum, extent),
         Buffer(BufferId::common_voxelize_normal_sum, extent),
         emissive ? Buffer(BufferId::common_voxelize_emission_sum, extent) : Buffer(),
         Buffer(BufferId::common_voxelize_opacity, extent),
         Buffer(BufferId::common_voxelize_albedo, extent),
         Buffer(BufferId::common_voxelize_normal, extent),
         emissive ? Buffer(BufferId::common_voxelize_emission, extent) : Buffer()};
  }
  // Only the blocks contributions reach are resolved where every other voxel already holds its
  // value: the frame before's outputs (a voxel resolves from its sums alone, and the update leaves
  // the others' sums as they were), or fresh buffers' +0 where that is what a voxel without
  // contributions resolves to (resolvesToZero).
  std::optional<TouchedBlocks> touched;
  if (moved || resolvesToZero(antialiased, emissive, ctx.triangles.emissionScale))
    touched.emplace(n);
  Accumulator acc{grid, v.weight, v.albedoSum, v.normalSum, emissive ? &v.emissionSum : nullptr};
  acc.touched = touched ? &*touched : nullptr;

  const TextureAccess textures{ctx.scene.textures};
  const auto walk = [&](const std::vector<shared::VoxelTriangle>& tris, size_t first, size_t end) {
    parallelFor(tbb::blocked_range<size_t>(first, end, 64), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        // A million copies of one triangle fail after the first few thousand, not after all.
        if (acc.overflow.load(std::memory_order_relaxed)) return;
        if (antialiased)
          antialiasedWalk(tris[i], n, textures, acc);
        else
          conservativeWalk(tris[i], n, textures, acc);
      }
    });
  };
  if (moved) {
    // Every subtraction before any addition, so that a running sum passes the bound only when
    // the final one does.
    acc.subtract = true;
    for (const auto& [first, end] : moved->before)
      walk(ctx.previous->triangles->triangles, first, end);
    acc.subtract = false;
    for (const auto& [first, end] : moved->now) walk(ctx.triangles.triangles, first, end);
  } else {
    walk(ctx.triangles.triangles, 0, ctx.triangles.triangles.size());
  }

  if (acc.overflow)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");

  const auto resolve = [&](size_t e) {
    const uint32_t w = v.weight.words[e];
    v.opacity.set(e, 0, shared::resolveOpacity(w, antialiased));
    auto sum3 = [&](const Buffer& b) {
      return glm::uvec3(b.words[3 * e], b.words[3 * e + 1], b.words[3 * e + 2]);
    };
    const glm::vec3 a = shared::resolveAverage(sum3(v.albedoSum), w);
    const glm::vec3 nm = shared::resolveNormal(glm::ivec3(sum3(v.normalSum)), w);
    for (int c = 0; c < 3; ++c) {
      v.albedo.set(e, c, a[c]);
      v.normal.set(e, c, nm[c]);
    }
    if (emissive) {
      const uint32_t* sum = &v.emissionSum.words[4 * e];
      const uint32_t over = emitterMean ? sum[3] : w;
      const glm::vec3 em = shared::resolveEmission(glm::uvec3(sum[0], sum[1], sum[2]), over,
                                                   ctx.triangles.emissionScale);
      for (int c = 0; c < 3; ++c) v.emission.set(e, c, em[c]);
    }
  };
  if (touched) {
    // Each block by one task, its voxels in index order.
    const std::vector<glm::ivec3> blocks = touched->list();
    const int side = 1 << TouchedBlocks::kShift;
    parallelFor(tbb::blocked_range<size_t>(0, blocks.size(), 8), [&](const auto& range) {
      for (size_t b = range.begin(); b != range.end(); ++b) {
        const glm::ivec3 high = glm::min(blocks[b] + side, glm::ivec3(n));
        for (int z = blocks[b].z; z < high.z; ++z)
          for (int y = blocks[b].y; y < high.y; ++y)
            for (int x = blocks[b].x; x < high.x; ++x) resolve(grid.index({x, y, z}));
      }
    });
  } else {
    parallelFor(tbb::blocked_range<size_t>(0, v.weight.elementCount(), 4096),
                [&](const auto& range) {
                  for (size_t e = range.begin(); e != range.end(); ++e) resolve(e);
                });
  }
  buffers.put(std::move(v.weight));
  buffers.put(std::move(v.albedoSum));
  buffers.put(std::move(v.normalSum));
  buffers.put(std::move(v.opacity));
  buffers.put(std::move(v.albedo));
  buffers.put(std::move(v.normal));
  if (emissive) {
    buffers.put(std::move(v.emissionSum));
    buffers.put(std::move(v.emission));
  }
}

}  // namespace voxgi::cpu
