// CPU bounce stage: the shared kernel (shaders/shared/cone/gather.h) per voxel, its cones
// marched in lanes (cpu/cone/gather_lanes.h), then the pyramid again, bounce.count times. Each
// voxel is written by one task, so any thread count gives the same bits.
#include <tbb/blocked_range.h>

#include "common/parallel.h"
#include "common/cone/cone_trace.h"
#include "common/vct/radiance_buffers.h"
#include "cpu/cone/cone_volumes.h"
#include "cpu/cone/gather_lanes.h"
#include "cpu/vct/pyramid.h"
#include "cpu/stages.h"
#include "shaders/shared/cone/gather.h"

namespace voxgi::cpu {
namespace {

// What the bounce kernel reads: the previous bounce through the cone tracer's accessor, and
// light_voxels' radiance with the voxel albedo and normal.
struct BounceVolumes {
  const ConeVolumes& previous;
  const Buffer& direct;
  const Buffer& albedo;
  const Buffer& normal;
  const GridSpec& grid;

  size_t index(glm::ivec3 v) const { return grid.index(v); }
  glm::vec4 pyramidAt(int level, int face, glm::ivec3 v) const {
    return previous.pyramidAt(level, face, v);
  }
  bool cellEmpty(int level, glm::ivec3 i) const { return previous.cellEmpty(level, i); }
  shared::ConeData coneAt(int i) const { return previous.coneAt(i); }
  glm::vec4 directAt(glm::ivec3 v) const {
    const size_t e = index(v);
    return {direct.vec3At(e), direct.get<float>(e, 3)};
  }
  glm::vec3 albedoAt(glm::ivec3 v) const { return albedo.vec3At(index(v)); }
  glm::vec3 normalAt(glm::ivec3 v) const { return normal.vec3At(index(v)); }
};

}  // namespace

void vct::bounce(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::vct_bounce, 2.0);  // the new bounce next to the previous one
  const int n = ctx.scene.grid.resolution;
  const ConeTraceSetup setup = prepareGather(ctx);
  const MipMode mode = ctx.settings.vct.mip;
  const RadianceBuffers first = directRadiance(mode);
  const Buffer& direct = buffers.at(first.radiance);
  Buffer radiance, pyramid;  // the latest bounce; before the first, light_voxels' and mip's
  for (int b = 0; b < ctx.settings.vct.bounceCount; ++b) {
    Buffer next(BufferId::vct_bounce_radiance, glm::ivec3(n));
    {
      const ConeVolumes previous(b == 0 ? direct : radiance,
                                 b == 0 ? buffers.at(first.pyramid) : pyramid, mode, n,
                                 setup.lights, setup.cones);
      const BounceVolumes volumes{previous, direct, buffers.at(BufferId::common_voxelize_albedo),
                                  buffers.at(BufferId::common_voxelize_normal), ctx.scene.grid};
      const cone_lanes::Volumes lanes = laneVolumes(previous);
      // shared::bounceVoxel per voxel, the rows' cones marched together in lanes.
      parallelFor(tbb::blocked_range<int>(0, n * n, 8), [&](const auto& rows) {
        std::vector<glm::ivec3> voxels;
        for (int row = rows.begin(); row != rows.end(); ++row)
          for (int x = 0; x < n; ++x) voxels.emplace_back(x, row % n, row / n);
        std::vector<glm::vec3> gathered(voxels.size());
        gatherVoxels(simdLevel(), volumes, lanes, voxels, setup.params, gathered);
        for (size_t i = 0; i < voxels.size(); ++i) {
          const glm::ivec3 v = voxels[i];
          const glm::vec4 r =
              shared::addReflected(volumes.directAt(v), volumes.albedoAt(v), gathered[i]);
          const size_t e = volumes.index(v);
          for (int c = 0; c < 4; ++c) next.set(e, c, r[c]);
        }
      });
    }
    radiance = std::move(next);
    buildPyramid(bufferSpec(pyramidBuffer(StageId::vct_bounce, mode)), radiance, n, pyramid);
  }
  buffers.put(std::move(radiance));
  buffers.put(std::move(pyramid));
}

}  // namespace voxgi::cpu
