// CPU trace_cones stage: the shared kernel's phases (shaders/shared/cone/pixel_light.h)
// per tile, with the cones of the tile's pixels marched in SIMD lanes (cpu/cone/tile_tracer.h):
// the same numbers tracePixel gives, faster. Each pixel is written by one task, so the image does
// not depend on the thread count.
#include <optional>
#include <vector>

#include <tbb/blocked_range2d.h>

#include "common/parallel.h"
#include "common/cone/cone_trace.h"
#include "common/vct/radiance_buffers.h"
#include "cpu/cone/cone_volumes.h"
#include "cpu/cone/tile_tracer.h"
#include "cpu/stages.h"
#include "shaders/shared/vct/diffuse_upsample.h"

namespace voxgi::cpu {
namespace {

// The stage's planned buffers, allocated; the others stay empty and are not written.
struct TermBuffers {
  Buffer directDiffuse, indirectDiffuse, directSpecular, indirectSpecular, ambient;

  TermBuffers(const EffectPlan& plan, glm::ivec3 extent) {
    const auto planned = [&](BufferId id) {
      return bufferNeeded(bufferSpec(id), plan) ? Buffer(id, extent) : Buffer();
    };
    directDiffuse = planned(BufferId::vct_trace_cones_direct_diffuse);
    indirectDiffuse = planned(BufferId::vct_trace_cones_indirect_diffuse);
    directSpecular = planned(BufferId::vct_trace_cones_direct_specular);
    indirectSpecular = planned(BufferId::vct_trace_cones_indirect_specular);
    ambient = planned(BufferId::vct_trace_cones_ambient_occlusion);
  }
  void write(size_t e, const shared::PixelLight& light) {
    directDiffuse.setVec3(e, light.directDiffuse);
    indirectDiffuse.setVec3(e, light.indirectDiffuse);
    if (directSpecular.spec != nullptr) directSpecular.setVec3(e, light.directSpecular);
    if (indirectSpecular.spec != nullptr) indirectSpecular.setVec3(e, light.indirectSpecular);
    if (ambient.spec != nullptr) ambient.set(e, 0, light.ambientOcclusion);
  }
  void putInto(BufferSet& buffers) {
    for (Buffer* b :
         {&directDiffuse, &indirectDiffuse, &directSpecular, &indirectSpecular, &ambient})
      if (b->spec != nullptr) buffers.put(std::move(*b));
  }
};

// The blocks' diffuse samples at cones.diffuse_scale > 1, read as blendAround's FETCH.
struct DiffuseSamples {
  glm::ivec2 blocks{0};
  std::vector<shared::DiffuseSample> samples;

  shared::DiffuseSample diffuseSampleAt(glm::ivec2 b) const {
    if (glm::any(glm::lessThan(b, glm::ivec2(0))) || glm::any(glm::greaterThanEqual(b, blocks)))
      return shared::noDiffuseSample();
    return samples[size_t(b.y) * size_t(blocks.x) + size_t(b.x)];
  }
};

// Each pixel's diffuse sum: blended from `samples` where one stands for it (when given), else
// its own cones.
std::vector<shared::DiffuseSum> pixelDiffuse(TileTracer& tracer,
                                             const std::vector<TilePixel>& pixels,
                                             const DiffuseSamples* samples,
                                             const shared::ConeTraceParams& params) {
  if (samples == nullptr) return tracer.traceDiffuse(pixels);
  std::vector<shared::DiffuseSum> sums(pixels.size());
  std::vector<TilePixel> own;
  std::vector<size_t> ownIndex;
  for (size_t k = 0; k < pixels.size(); ++k) {
    const TilePixel& px = pixels[k];
    const shared::DiffuseBlend b =
        shared::blendAround(*samples, px.at, px.p, px.n, params.diffuseScale);
    if (shared::blendFound(b)) {
      sums[k] = shared::blendedDiffuse(b);
    } else {
      own.push_back(px);
      ownIndex.push_back(k);
    }
  }
  const std::vector<shared::DiffuseSum> traced = tracer.traceDiffuse(own);
  for (size_t i = 0; i < own.size(); ++i) sums[ownIndex[i]] = traced[i];
  return sums;
}

}  // namespace

void vct::trace_cones(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_trace_cones);
  const int n = ctx.scene.grid.resolution;
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const RadianceBuffers lit = finalRadiance(ctx);
  const ConeVolumes volumes(buffers.at(lit.radiance), buffers.at(lit.pyramid), ctx.settings.vct.mip,
                            n, setup.lights, setup.cones);
  const Buffer& position = buffers.at(BufferId::common_gbuffer_pixel_position);
  const Buffer& normal = buffers.at(BufferId::common_gbuffer_pixel_normal);
  const Buffer& objectId = buffers.at(BufferId::common_gbuffer_object_id);
  const glm::ivec3 extent = position.extent;
  TermBuffers terms(ctx.plan, extent);

  const cone_lanes::Volumes lanes = laneVolumes(volumes);
  const auto pixelAt = [&](glm::ivec2 at) {
    const size_t e = size_t(at.y) * size_t(extent.x) + size_t(at.x);
    return tilePixel(e, at, position.vec3At(e), normal.vec3At(e),
                     setup.objects.at(objectId.get<uint32_t>(e, 0)), setup.params);
  };
  const auto surfaceAt = [&](glm::ivec2 at) {
    return objectId.get<uint32_t>(size_t(at.y) * size_t(extent.x) + size_t(at.x), 0) != 0u;
  };

  // At cones.diffuse_scale > 1: each block's sample, its first candidate pixel with a surface.
  const int scale = setup.params.diffuseScale;
  std::optional<DiffuseSamples> samples;
  if (scale > 1) {
    samples.emplace();
    samples->blocks = (glm::ivec2(extent) + scale - 1) / scale;
    samples->samples.assign(size_t(samples->blocks.x) * size_t(samples->blocks.y),
                            shared::noDiffuseSample());
    const tbb::blocked_range2d<int> blockTiles(0, samples->blocks.y, 8, 0, samples->blocks.x, 8);
    parallelFor(blockTiles, [&](const tbb::blocked_range2d<int>& tile) {
      std::vector<TilePixel> pixels;
      std::vector<size_t> slots;
      for (int by = tile.rows().begin(); by != tile.rows().end(); ++by)
        for (int bx = tile.cols().begin(); bx != tile.cols().end(); ++bx)
          for (int k = 0; k < scale * scale; ++k) {
            const glm::ivec2 at = glm::ivec2(bx, by) * scale + shared::blockCandidate(k, scale);
            if (at.x >= extent.x || at.y >= extent.y || !surfaceAt(at)) continue;
            pixels.push_back(pixelAt(at));
            slots.push_back(size_t(by) * size_t(samples->blocks.x) + size_t(bx));
            break;
          }
      TileTracer tracer(lanes, setup.lights, setup.cones, setup.params);
      const std::vector<shared::DiffuseSum> sums = tracer.traceDiffuse(pixels);
      for (size_t i = 0; i < pixels.size(); ++i)
        samples->samples[slots[i]] = shared::diffuseSample(pixels[i].p, pixels[i].n, sums[i]);
    });
  }

  // 8x8 tiles: neighbouring pixels' cones read the same voxels (cache) and end after similar
  // numbers of steps (lanes), and small tasks balance pixels of very different cost.
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  parallelFor(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    std::vector<TilePixel> pixels;
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x)
        if (surfaceAt({x, y})) pixels.push_back(pixelAt({x, y}));  // background: every term 0
    TileTracer tracer(lanes, setup.lights, setup.cones, setup.params);
    tracer.addDirectLight(pixels);
    const std::vector<shared::DiffuseSum> diffuse =
        pixelDiffuse(tracer, pixels, samples ? &*samples : nullptr, setup.params);
    const std::vector<shared::PixelLight> lights = tracer.finish(pixels, diffuse);
    for (size_t k = 0; k < pixels.size(); ++k) terms.write(pixels[k].e, lights[k]);
  });
  terms.putInto(buffers);
}

}  // namespace voxgi::cpu
