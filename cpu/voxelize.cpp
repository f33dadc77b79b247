// CPU voxelize stage: every (triangle, voxel) pair the shared kernel accepts is accumulated with
// integer atomics (order-independent, so bit-identical for any thread count), then resolved.
#include <atomic>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/parallel.h"
#include "common/voxel_overflow.h"
#include "common/voxel_walk.h"
#include "cpu/stages.h"

namespace voxgi::cpu {
namespace {

using shared::VoxelContribution;
using shared::VoxelTriangle;

struct Accumulator {
  const GridSpec& grid;
  Buffer& weight;
  Buffer& albedo;
  Buffer& normal;
  Buffer* emission;  // null when the scene emits nothing
  // Set by the first contribution that takes a voxel past kMaxWeightSum: the sums of that voxel
  // are lost, the stage fails, so the remaining triangles are skipped.
  std::atomic<bool> overflow{false};

  static void add(uint32_t& word, uint32_t value) {
    std::atomic_ref<uint32_t>(word).fetch_add(value, std::memory_order_relaxed);
  }

  void operator()(const glm::ivec3& voxel, const VoxelContribution& c) {
    const size_t e = grid.index(voxel);
    const uint32_t old =
        std::atomic_ref<uint32_t>(weight.words[e]).fetch_add(c.weight, std::memory_order_relaxed);
    if (uint64_t(old) + c.weight > shared::kMaxWeightSum)
      overflow.store(true, std::memory_order_relaxed);
    for (int i = 0; i < 3; ++i) {
      add(albedo.words[3 * e + size_t(i)], c.albedo[i]);
      add(normal.words[3 * e + size_t(i)], static_cast<uint32_t>(c.normal[i]));  // two's complement
      if (emission != nullptr) add(emission->words[4 * e + size_t(i)], c.emission[i]);
    }
    if (emission != nullptr) add(emission->words[4 * e + 3], c.emitterWeight);
  }
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
  Buffer weight(BufferId::common_voxelize_weight_sum, extent);
  Buffer albedoSum(BufferId::common_voxelize_albedo_sum, extent);
  Buffer normalSum(BufferId::common_voxelize_normal_sum, extent);
  Buffer emissionSum = emissive ? Buffer(BufferId::common_voxelize_emission_sum, extent) : Buffer();
  Accumulator acc{grid, weight, albedoSum, normalSum, emissive ? &emissionSum : nullptr};

  const auto& tris = ctx.triangles.triangles;
  const TextureAccess textures{ctx.scene.textures};
  parallelFor(tbb::blocked_range<size_t>(0, tris.size(), 64), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      // A million copies of one triangle fail after the first few thousand, not after all.
      if (acc.overflow.load(std::memory_order_relaxed)) return;
      if (antialiased)
        antialiasedWalk(tris[i], n, textures, acc);
      else
        conservativeWalk(tris[i], n, textures, acc);
    }
  });

  if (acc.overflow)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");

  Buffer opacity(BufferId::common_voxelize_opacity, extent);
  Buffer albedo(BufferId::common_voxelize_albedo, extent);
  Buffer normal(BufferId::common_voxelize_normal, extent);
  Buffer emission = emissive ? Buffer(BufferId::common_voxelize_emission, extent) : Buffer();
  parallelFor(tbb::blocked_range<size_t>(0, weight.elementCount(), 4096), [&](const auto& range) {
    for (size_t e = range.begin(); e != range.end(); ++e) {
      const uint32_t w = weight.words[e];
      opacity.set(e, 0, shared::resolveOpacity(w, antialiased));
      auto sum3 = [&](const Buffer& b) {
        return glm::uvec3(b.words[3 * e], b.words[3 * e + 1], b.words[3 * e + 2]);
      };
      const glm::vec3 a = shared::resolveAverage(sum3(albedoSum), w);
      const glm::vec3 nm = shared::resolveNormal(glm::ivec3(sum3(normalSum)), w);
      for (int c = 0; c < 3; ++c) {
        albedo.set(e, c, a[c]);
        normal.set(e, c, nm[c]);
      }
      if (emissive) {
        const uint32_t* sum = &emissionSum.words[4 * e];
        const uint32_t over = emitterMean ? sum[3] : w;
        const glm::vec3 em = shared::resolveEmission(glm::uvec3(sum[0], sum[1], sum[2]), over,
                                                     ctx.triangles.emissionScale);
        for (int c = 0; c < 3; ++c) emission.set(e, c, em[c]);
      }
    }
  });
  buffers.put(std::move(weight));
  buffers.put(std::move(albedoSum));
  buffers.put(std::move(normalSum));
  buffers.put(std::move(opacity));
  buffers.put(std::move(albedo));
  buffers.put(std::move(normal));
  if (emissive) {
    buffers.put(std::move(emissionSum));
    buffers.put(std::move(emission));
  }
}

}  // namespace voxgi::cpu
