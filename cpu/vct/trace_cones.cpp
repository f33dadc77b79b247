// CPU trace_cones stage: the shared kernel's phases (shaders/shared/vct/trace_cones_kernel.h)
// per tile, with the cones of the tile's pixels marched in SIMD lanes (cpu/vct/cone_lanes.h):
// the same numbers tracePixel gives, faster. Each pixel is written by one task, so the image does
// not depend on the thread count.
#include <optional>
#include <vector>

#include <tbb/blocked_range2d.h>

#include "common/parallel.h"
#include "common/vct/trace_cones.h"
#include "common/vct/radiance_buffers.h"
#include "cpu/vct/cone_lanes.h"
#include "cpu/stages.h"
#include "shaders/shared/vct/diffuse_upsample.h"

namespace voxgi::cpu {
namespace {

// A pixel of a tile with a surface, what its cones start from, and its direct light as the lights
// add up.
struct Pixel {
  size_t e;
  glm::ivec2 at;
  glm::vec3 p, n, origin, mirror;
  glm::vec3 tangent, bitangent;  // the diffuse cones' frame around n
  shared::ObjectData object;
  shared::DirectLight direct;
};

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

// The kernel's phases over one tile's pixels, each phase's cones marched together in lanes.
class TileTracer {
 public:
  TileTracer(const ConeVolumes& volumes, const ConeTraceSetup& setup)
      : volumes_(volumes), params_(setup.params) {}

  // Direct light, one light at a time in the kernel's order.
  void addDirectLight(std::vector<Pixel>& pixels) {
    std::vector<shared::LightPath> paths(pixels.size());
    for (int i = 0; i < params_.lightCount; ++i) {
      jobs_.clear();
      for (size_t k = 0; k < pixels.size(); ++k) {
        const Pixel& px = pixels[k];
        paths[k] = shared::lightPath(volumes_.lightAt(i), px.p, px.n, params_);
        if (paths[k].arrives && paths[k].shadowLength > 0.0f)
          jobs_.push_back({px.origin, paths[k].toLight, paths[k].cosine, paths[k].tanHalf,
                           paths[k].shadowLength});
      }
      march(shared::shadowMarchKind(params_));
      size_t hit = 0;
      for (size_t k = 0; k < pixels.size(); ++k) {
        if (!paths[k].arrives) continue;
        const float visibility =
            paths[k].shadowLength > 0.0f ? 1.0f - hits_[hit++].occlusion : 1.0f;
        Pixel& px = pixels[k];
        px.direct =
            shared::addLight(px.direct, paths[k], visibility, px.mirror, px.object, params_);
      }
    }
  }

  // Each pixel's diffuse sum: blended from `samples` where one stands for it (when given), else
  // its own cones.
  std::vector<shared::DiffuseSum> diffuse(const std::vector<Pixel>& pixels,
                                          const DiffuseSamples* samples) {
    if (samples == nullptr) return traceDiffuse(pixels);
    std::vector<shared::DiffuseSum> sums(pixels.size());
    std::vector<Pixel> own;
    std::vector<size_t> ownIndex;
    for (size_t k = 0; k < pixels.size(); ++k) {
      const Pixel& px = pixels[k];
      const shared::DiffuseBlend b =
          shared::blendAround(*samples, px.at, px.p, px.n, params_.diffuseScale);
      if (shared::blendFound(b)) {
        sums[k] = shared::blendedDiffuse(b);
      } else {
        own.push_back(px);
        ownIndex.push_back(k);
      }
    }
    const std::vector<shared::DiffuseSum> traced = traceDiffuse(own);
    for (size_t i = 0; i < own.size(); ++i) sums[ownIndex[i]] = traced[i];
    return sums;
  }

  // The diffuse cones, cone by cone: a lane's next cone is its neighbour's, much like it.
  std::vector<shared::DiffuseSum> traceDiffuse(const std::vector<Pixel>& pixels) {
    const int coneCount = params_.diffuseConeCount;
    jobs_.clear();
    for (int c = 0; c < coneCount; ++c)
      for (const Pixel& px : pixels) {
        const shared::ConeData cone = volumes_.coneAt(c);
        jobs_.push_back({px.origin,
                         shared::diffuseConeDirection(px.tangent, px.bitangent, px.n, cone),
                         cone.direction.z, cone.tanHalfAperture, params_.maxDistance});
      }
    march(shared::diffuseMarchKind(params_));
    std::vector<shared::DiffuseSum> sums(pixels.size(), shared::noDiffuse());
    for (int c = 0; c < coneCount; ++c)
      for (size_t k = 0; k < pixels.size(); ++k)
        sums[k] = shared::addDiffuseCone(sums[k], hits_[size_t(c) * pixels.size() + k],
                                         volumes_.coneAt(c));
    return sums;
  }

  // The specular cones of glossy pixels, then every pixel's terms.
  void finish(const std::vector<Pixel>& pixels, const std::vector<shared::DiffuseSum>& diffuse,
              TermBuffers& out) {
    jobs_.clear();
    for (const Pixel& px : pixels)
      if (px.object.specularTanHalfAperture > 0.0f)
        jobs_.push_back({px.origin, px.mirror, shared::dot3(px.n, px.mirror),
                         px.object.specularTanHalfAperture, params_.maxDistance});
    march(shared::kMarchRadiance);
    size_t specular = 0;
    for (size_t k = 0; k < pixels.size(); ++k) {
      const Pixel& px = pixels[k];
      const shared::ConeHit specularHit =
          px.object.specularTanHalfAperture > 0.0f ? hits_[specular++] : shared::noConeHit();
      out.write(px.e, shared::finishPixel(px.direct, diffuse[k], specularHit, px.object, params_));
    }
  }

 private:
  void march(int kind) {
    hits_.resize(jobs_.size());
    marchCones(volumes_, jobs_, kind, params_, hits_);
  }

  const ConeVolumes& volumes_;
  const shared::ConeTraceParams& params_;
  std::vector<ConeJob> jobs_;
  std::vector<shared::ConeHit> hits_;
};

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

  const auto pixelAt = [&](glm::ivec2 at) {
    const size_t e = size_t(at.y) * size_t(extent.x) + size_t(at.x);
    const glm::vec3 p = position.vec3At(e), nrm = normal.vec3At(e);
    glm::vec3 t, b;
    shared::tangentFrame(nrm, t, b);
    return Pixel{e,
                 at,
                 p,
                 nrm,
                 shared::coneOrigin(p, nrm, setup.params),
                 shared::mirrorDirection(p, nrm, setup.params),
                 t,
                 b,
                 setup.objects.at(objectId.get<uint32_t>(e, 0)),
                 shared::noDirectLight()};
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
      std::vector<Pixel> pixels;
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
      TileTracer tracer(volumes, setup);
      const std::vector<shared::DiffuseSum> sums = tracer.traceDiffuse(pixels);
      for (size_t i = 0; i < pixels.size(); ++i)
        samples->samples[slots[i]] = shared::diffuseSample(pixels[i].p, pixels[i].n, sums[i]);
    });
  }

  // 8x8 tiles: neighbouring pixels' cones read the same voxels (cache) and end after similar
  // numbers of steps (lanes), and small tasks balance pixels of very different cost.
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  parallelFor(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    std::vector<Pixel> pixels;
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x)
        if (surfaceAt({x, y})) pixels.push_back(pixelAt({x, y}));  // background: every term 0
    TileTracer tracer(volumes, setup);
    tracer.addDirectLight(pixels);
    const std::vector<shared::DiffuseSum> diffuse =
        tracer.diffuse(pixels, samples ? &*samples : nullptr);
    tracer.finish(pixels, diffuse, terms);
  });
  terms.putInto(buffers);
}

}  // namespace voxgi::cpu
