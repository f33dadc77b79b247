// CPU light_voxels stage: the shared kernel (shaders/shared/cone/voxel_light.h) per voxel,
// a row of voxels at a time with their visibility rays in SIMD lanes (voxel_light_lanes.h). Each
// voxel is written by exactly one task, so the result does not depend on the thread count.
#include <bit>

#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/vct/light_voxels.h"
#include "cpu/stages.h"
#include "cpu/cone/voxel_light_lanes.h"
#include "shaders/shared/morton.h"

namespace voxgi::cpu {
namespace {

// The volumes the kernel reads (FETCH in the shared code).
struct LightVoxelsVolumes {
  const Buffer& opacity;
  const Buffer& albedo;
  const Buffer& normal;
  const Buffer* emission;
  const std::vector<shared::LightData>& lights;
  const GridSpec& grid;

  size_t index(glm::ivec3 v) const { return grid.index(v); }
  float opacityAt(glm::ivec3 v) const { return opacity.get<float>(index(v), 0); }
  glm::vec3 albedoAt(glm::ivec3 v) const { return albedo.vec3At(index(v)); }
  glm::vec3 normalAt(glm::ivec3 v) const { return normal.vec3At(index(v)); }
  glm::vec3 emissionAt(glm::ivec3 v) const { return emission->vec3At(index(v)); }
  shared::LightData lightAt(int i) const { return lights[size_t(i)]; }
};

// The lanes' map of the voxels with opacity above 0 (ShadowVolume::mayBeOpaque): a bit per Morton
// key of the power-of-two cube around the grid, each word found by one task. A word's 32 keys
// are a 4 x 4 x 2 block at fixed offsets from its first.
std::vector<uint32_t> opaqueVoxels(const LightVoxelsVolumes& volumes, int n) {
  const size_t side = std::bit_ceil(size_t(n));
  std::vector<uint32_t> words(std::max<size_t>(side * side * side / 32, 1), 0u);
  glm::ivec3 offsets[32];
  for (uint32_t bit = 0; bit < 32; ++bit) offsets[bit] = glm::ivec3(shared::mortonDecode(bit));
  parallelFor(tbb::blocked_range<size_t>(0, words.size(), 1024), [&](const auto& range) {
    for (size_t w = range.begin(); w != range.end(); ++w) {
      const glm::ivec3 first(shared::mortonDecode(uint32_t(w * 32)));
      uint32_t word = 0;
      for (uint32_t bit = 0; bit < 32; ++bit) {
        const glm::ivec3 v = first + offsets[bit];
        if (v.x < n && v.y < n && v.z < n && volumes.opacityAt(v) > 0.0f) word |= 1u << bit;
      }
      words[w] = word;
    }
  });
  return words;
}

// Grids up to 512 voxels a side march their rays in lanes (the map: 16 MiB at 512^3).
constexpr int kMostLaneResolution = 512;

}  // namespace

void vct::light_voxels(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_light_voxels);
  const int n = ctx.scene.grid.resolution;
  const Buffer* emission = buffers.find(BufferId::common_voxelize_emission);
  const LightVoxelsSetup setup = prepareLightVoxels(ctx, emission != nullptr);
  const LightVoxelsVolumes volumes{buffers.at(BufferId::common_voxelize_opacity),
                                   buffers.at(BufferId::common_voxelize_albedo),
                                   buffers.at(BufferId::common_voxelize_normal),
                                   emission,
                                   setup.lights,
                                   ctx.scene.grid};
  const shared::LightVoxelsUpdate update = lightVoxelsUpdate(ctx, setup, emission != nullptr);
  // A partial update starts from the frame before's radiance and relights only the voxels whose
  // inputs can have changed; a whole one rewrites every voxel of it (its pages stay mapped).
  Buffer radiance = ctx.previous != nullptr
                        ? ctx.previous->stash.take(BufferId::vct_light_voxels_radiance)
                        : Buffer{};
  if (radiance.spec == nullptr || radiance.extent != glm::ivec3(n))
    radiance = Buffer(BufferId::vct_light_voxels_radiance, glm::ivec3(n));
  const auto store = [&](glm::ivec3 v, const glm::vec4& r) {
    const size_t e = volumes.index(v);
    for (int c = 0; c < 4; ++c) radiance.set(e, c, r[c]);
  };
  // Grids above kMostLaneResolution light voxel by voxel with the kernel itself.
  const bool lanes = n <= kMostLaneResolution;
  const std::vector<uint32_t> opaque = lanes ? opaqueVoxels(volumes, n) : std::vector<uint32_t>{};
  const ShadowRays<LightVoxelsVolumes> rays{&volumes, &setup.params};
  const ShadowVolume shadow = rays.volume(opaque.data());
  parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
    std::vector<glm::ivec3> voxels;
    for (int row = rows.begin(); row != rows.end(); ++row)
      for (int x = 0; x < n; ++x) {
        const glm::ivec3 v(x, row % n, row / n);
        if (update.partial == 1 && !shared::lightVoxelMayChange(volumes, v, setup.params, update))
          continue;
        if (!lanes)
          store(v, shared::lightVoxel(volumes, v, setup.params));
        else if (volumes.opacityAt(v) <= 0.0f)  // lightVoxel's answer, without a batch slot
          store(v, glm::vec4(0.0f));
        else
          voxels.push_back(v);
      }
    std::vector<glm::vec4> lit(voxels.size());
    lightVoxels(simdLevel(), volumes, shadow, voxels, setup.params, lit);
    for (size_t i = 0; i < voxels.size(); ++i) store(voxels[i], lit[i]);
  });
  buffers.put(std::move(radiance));
}

}  // namespace voxgi::cpu
