// CPU voxelize stage: every (triangle, voxel) pair the shared kernel accepts is accumulated with
// integer atomics (order-independent, so bit-identical for any thread count), then resolved.
#include <atomic>
#include <limits>

#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/error.h"
#include "cpu/stages.h"
#include "shaders/shared/voxelize_kernel.h"

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
  std::atomic<bool> overflow{false};

  static void add(uint32_t& word, uint32_t value) {
    std::atomic_ref<uint32_t>(word).fetch_add(value, std::memory_order_relaxed);
  }

  void operator()(const glm::ivec3& voxel, const VoxelContribution& c) {
    const size_t e = grid.index(voxel);
    const uint32_t old =
        std::atomic_ref<uint32_t>(weight.words[e]).fetch_add(c.weight, std::memory_order_relaxed);
    if (old > std::numeric_limits<uint32_t>::max() - c.weight) overflow = true;
    for (int i = 0; i < 3; ++i) {
      add(albedo.words[3 * e + size_t(i)], c.albedo[i]);
      add(normal.words[3 * e + size_t(i)], static_cast<uint32_t>(c.normal[i]));  // two's complement
      if (emission != nullptr) add(emission->words[3 * e + size_t(i)], c.emission[i]);
    }
  }
};

bool inside(const glm::ivec3& v, int n) {
  return v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < n && v.y < n && v.z < n;
}

void conservativeTriangle(const VoxelTriangle& t, int n, Accumulator& acc) {
  const unsigned axis = t.info.x;
  const glm::vec3 p0 = shared::toDominant(glm::vec3(t.v0), axis);
  const glm::vec3 p1 = shared::toDominant(glm::vec3(t.v1), axis);
  const glm::vec3 p2 = shared::toDominant(glm::vec3(t.v2), axis);
  const glm::vec3 lo = glm::min(p0, glm::min(p1, p2));
  const glm::vec3 hi = glm::max(p0, glm::max(p1, p2));
  // Closed columns: column u spans [u, u+1], so it touches [lo, hi] iff ceil(lo) - 1 <= u <=
  // floor(hi).
  const int u0 = std::max(0, int(std::ceil(lo.x)) - 1), u1 = std::min(n - 1, int(std::floor(hi.x)));
  const int w0 = std::max(0, int(std::ceil(lo.y)) - 1), w1 = std::min(n - 1, int(std::floor(hi.y)));
  VoxelContribution c{};
  for (int cw = w0; cw <= w1; ++cw)
    for (int cu = u0; cu <= u1; ++cu) {
      const glm::ivec2 layers = shared::columnLayers(t, {cu, cw}, n);
      for (int k = layers.x; k <= layers.y; ++k) {
        const glm::ivec3 voxel = shared::fromDominant({cu, cw, k}, axis);
        if (shared::conservativeContribution(t, voxel, c)) acc(voxel, c);
      }
    }
}

void antialiasedTriangle(const VoxelTriangle& t, int n, Accumulator& acc) {
  for (int i = 0; i < int(t.info.y); ++i)
    for (int k = 0; k < shared::antialiasedRowSamples(t, i); ++k) {
      const glm::vec3 p = shared::antialiasedRowSample(t, i, k);
      const glm::ivec3 base = shared::tentBase(p);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 voxel = shared::tentCorner(base, corner);
        if (!inside(voxel, n)) continue;
        const unsigned w = shared::tentWeight(t, p, base, corner);
        if (w != 0u) acc(voxel, shared::weightedContribution(t, w));
      }
    }
}

}  // namespace

void common::voxelize(const StageContext& ctx, BufferSet& buffers) {
  const GridSpec& grid = ctx.scene.grid;
  const int n = grid.resolution;
  checkStageMemory(ctx, StageId::common_voxelize);
  const bool antialiased = ctx.settings.voxelizeMode == VoxelizeMode::antialiased;
  const bool emissive =
      ctx.plan.on(Effect::emission);  // emissionScale may be 0 under plan.mode=full
  const glm::ivec3 extent(n);
  Buffer weight(BufferId::common_voxelize_weight_sum, extent);
  Buffer albedoSum(BufferId::common_voxelize_albedo_sum, extent);
  Buffer normalSum(BufferId::common_voxelize_normal_sum, extent);
  Buffer emissionSum = emissive ? Buffer(BufferId::common_voxelize_emission_sum, extent) : Buffer();
  Accumulator acc{grid, weight, albedoSum, normalSum, emissive ? &emissionSum : nullptr};

  const auto& tris = ctx.triangles.triangles;
  parallelFor(tbb::blocked_range<size_t>(0, tris.size(), 64), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (antialiased)
        antialiasedTriangle(tris[i], n, acc);
      else
        conservativeTriangle(tris[i], n, acc);
    }
  });

  Buffer opacity(BufferId::common_voxelize_opacity, extent);
  Buffer albedo(BufferId::common_voxelize_albedo, extent);
  Buffer normal(BufferId::common_voxelize_normal, extent);
  Buffer emission = emissive ? Buffer(BufferId::common_voxelize_emission, extent) : Buffer();
  std::atomic<bool> tooHeavy{false};
  parallelFor(tbb::blocked_range<size_t>(0, weight.elementCount(), 4096), [&](const auto& range) {
    for (size_t e = range.begin(); e != range.end(); ++e) {
      const uint32_t w = weight.words[e];
      if (w > shared::kMaxWeightSum) tooHeavy = true;
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
        const glm::vec3 em =
            shared::resolveEmission(sum3(emissionSum), w, ctx.triangles.emissionScale);
        for (int c = 0; c < 3; ++c) emission.set(e, c, em[c]);
      }
    }
  });
  if (acc.overflow || tooHeavy)
    throw InputError(ctx.scene.file, "meshes",
                     "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                     "overflow); lower grid.resolution or remove overlapping copies");

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
