// CPU trace_cones stage: the shared kernel's phases (shaders/shared/vct/trace_cones_kernel.h)
// per tile, with the cones of the tile's pixels marched in SIMD lanes (cpu/vct/cone_lanes.h):
// the same numbers tracePixel gives, faster. Each pixel is written by one task, so the image does
// not depend on the thread count.
#include <vector>

#include <tbb/blocked_range2d.h>

#include "common/parallel.h"
#include "common/vct/kernel_params.h"
#include "common/vct/radiance_buffers.h"
#include "cpu/vct/cone_lanes.h"
#include "cpu/stages.h"
#include "shaders/shared/vct/trace_cones_kernel.h"

namespace voxgi::cpu {
void vct::trace_cones(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_trace_cones);
  const Scene& scene = ctx.scene;
  const int n = scene.grid.resolution;
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const RadianceBuffers lit = finalRadiance(ctx);
  const ConeVolumes volumes(buffers.at(lit.radiance), buffers.at(lit.pyramid), ctx.settings.vct.mip,
                            n, setup.lights, setup.cones);

  const Buffer& position = buffers.at(BufferId::common_gbuffer_pixel_position);
  const Buffer& normal = buffers.at(BufferId::common_gbuffer_pixel_normal);
  const Buffer& objectId = buffers.at(BufferId::common_gbuffer_object_id);
  const glm::ivec3 extent = position.extent;
  // The planned buffers of the stage, allocated; the others stay empty and are not written.
  const auto planned = [&](BufferId id) {
    return bufferNeeded(bufferSpec(id), ctx.plan) ? Buffer(id, extent) : Buffer();
  };
  Buffer directDiffuse = planned(BufferId::vct_trace_cones_direct_diffuse);
  Buffer indirectDiffuse = planned(BufferId::vct_trace_cones_indirect_diffuse);
  Buffer directSpecular = planned(BufferId::vct_trace_cones_direct_specular);
  Buffer indirectSpecular = planned(BufferId::vct_trace_cones_indirect_specular);
  Buffer ambient = planned(BufferId::vct_trace_cones_ambient_occlusion);

  // 8x8 tiles: neighbouring pixels' cones read the same voxels (cache) and end after similar
  // numbers of steps (lanes), and small tasks balance pixels of very different cost.
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  parallelFor(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    struct Pixel {
      size_t e;
      glm::vec3 p, n, origin, mirror;
      glm::vec3 tangent, bitangent;  // the diffuse cones' frame around n
      shared::ObjectData object;
      shared::DirectLight direct;
    };
    std::vector<Pixel> pixels;
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
        const size_t e = size_t(y) * size_t(extent.x) + size_t(x);
        const uint32_t id = objectId.get<uint32_t>(e, 0);
        if (id == 0u) continue;  // background: every term stays 0
        const glm::vec3 p = position.vec3At(e), nrm = normal.vec3At(e);
        glm::vec3 t, b;
        shared::tangentFrame(nrm, t, b);
        pixels.push_back({e, p, nrm, shared::coneOrigin(p, nrm, setup.params),
                          shared::mirrorDirection(p, nrm, setup.params), t, b, setup.objects.at(id),
                          shared::noDirectLight()});
      }
    std::vector<ConeJob> jobs;
    std::vector<shared::ConeHit> hits;
    const auto march = [&](int kind) {
      hits.resize(jobs.size());
      marchCones(volumes, jobs, kind, setup.params, hits);
    };
    // Direct light, one light at a time in the kernel's order.
    std::vector<shared::LightPath> paths(pixels.size());
    for (int i = 0; i < setup.params.modes.x; ++i) {
      jobs.clear();
      for (size_t k = 0; k < pixels.size(); ++k) {
        const Pixel& px = pixels[k];
        paths[k] = shared::lightPath(volumes.lightAt(i), px.p, px.n, setup.params);
        if (paths[k].arrives && paths[k].shadowLength > 0.0f)
          jobs.push_back({px.origin, paths[k].toLight, paths[k].cosine, paths[k].tanHalf,
                          paths[k].shadowLength});
      }
      march(shared::shadowMarchKind(setup.params));
      size_t hit = 0;
      for (size_t k = 0; k < pixels.size(); ++k) {
        if (!paths[k].arrives) continue;
        const float visibility = paths[k].shadowLength > 0.0f ? 1.0f - hits[hit++].occlusion : 1.0f;
        Pixel& px = pixels[k];
        px.direct =
            shared::addLight(px.direct, paths[k], visibility, px.mirror, px.object, setup.params);
      }
    }
    // The diffuse cones, cone by cone: a lane's next cone is its neighbour's, much like it.
    const int coneCount = setup.params.grid.w;
    jobs.clear();
    for (int c = 0; c < coneCount; ++c)
      for (const Pixel& px : pixels) {
        const shared::ConeData cone = volumes.coneAt(c);
        jobs.push_back({px.origin,
                        shared::diffuseConeDirection(px.tangent, px.bitangent, px.n, cone),
                        cone.direction.z, cone.direction.w, setup.params.march.w});
      }
    march(shared::diffuseMarchKind(setup.params));
    std::vector<shared::DiffuseSum> diffuse(pixels.size(), shared::noDiffuse());
    for (int c = 0; c < coneCount; ++c)
      for (size_t k = 0; k < pixels.size(); ++k)
        diffuse[k] = shared::addDiffuseCone(diffuse[k], hits[size_t(c) * pixels.size() + k],
                                            volumes.coneAt(c));
    // The specular cones of glossy pixels.
    jobs.clear();
    for (const Pixel& px : pixels)
      if (px.object.specular.x > 0.0f)
        jobs.push_back({px.origin, px.mirror, shared::dot3(px.n, px.mirror), px.object.specular.x,
                        setup.params.march.w});
    march(shared::kMarchRadiance);
    size_t specular = 0;
    for (size_t k = 0; k < pixels.size(); ++k) {
      const Pixel& px = pixels[k];
      const shared::ConeHit specularHit =
          px.object.specular.x > 0.0f ? hits[specular++] : shared::noConeHit();
      const shared::PixelLight light =
          shared::finishPixel(px.direct, diffuse[k], specularHit, px.object, setup.params);
      const size_t e = px.e;
      directDiffuse.setVec3(e, light.directDiffuse);
      indirectDiffuse.setVec3(e, light.indirectDiffuse);
      if (directSpecular.spec != nullptr) directSpecular.setVec3(e, light.directSpecular);
      if (indirectSpecular.spec != nullptr) indirectSpecular.setVec3(e, light.indirectSpecular);
      if (ambient.spec != nullptr) ambient.set(e, 0, light.ambientOcclusion);
    }
  });
  for (Buffer* b : {&directDiffuse, &indirectDiffuse, &directSpecular, &indirectSpecular, &ambient})
    if (b->spec != nullptr) buffers.put(std::move(*b));
}

}  // namespace voxgi::cpu
