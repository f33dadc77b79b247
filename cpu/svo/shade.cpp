// CPU shade stage: per pixel, trace_cones' direct light with a shadow cone per light and the
// specular cone, read through the tree's bricks (no diffuse cones: the leaves hold the diffuse
// light), plus the leaves' gathered light through their bricks (shaders/shared/svo/shade_kernel.h),
// composed as the dense technique composes (compose.h). The twin of shaders/svo/shade.comp.
// A tile's cones march together in SIMD lanes (cpu/cone/tile_tracer.h), as trace_cones' do: the
// numbers tracePixel gives.
#include <tbb/blocked_range2d.h>

#include "common/gbuffer.h"
#include "common/parallel.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/svo_volumes.h"
#include "cpu/cone/tile_tracer.h"
#include "shaders/shared/compose.h"
#include "shaders/shared/svo/shade_kernel.h"
#include "shaders/shared/cone/pixel_light.h"

namespace voxgi::cpu {

void svo::shade(const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  checkStageMemory(ctx, StageId::svo_shade);
  const int depth = treeDepth(ctx.scene);
  const Octree o = octreeFromWords(treeWords(buffers), depth);
  const Leaves leaves = treeLeaves(buffers);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_radiance));
  const NodeLevels mips = nodeLevels(buffers.at(BufferId::svo_mip_node_faces), o.tiles, depth);
  const Words bricks = floatWords(buffers.at(BufferId::svo_propagate_gathered_bricks));
  // The cones' trilinear cells from bricks (cpu/svo/svo_volumes.h), one tile lookup each.
  const TreeBricks cells = treeBricks(o, radiance, mips);
  const ConeTraceSetup trace = treeConeTrace(ctx, depth);
  const bool tricubic = ctx.settings.svo.shadeFilter == SvoShadeFilter::tricubic;
  const glm::vec3 background = ctx.scene.background;

  const GbufferView gbuffer(buffers);
  const Buffer &position = gbuffer.position, &normal = gbuffer.normal, &albedo = gbuffer.albedo,
               &specular = gbuffer.specular, *emission = gbuffer.emission,
               &object = gbuffer.objectId;
  const glm::ivec3 extent = position.extent;
  using Field = glm::vec3 shared::PixelLight::*;
  const std::pair<BufferId, Field> terms[] = {
      {BufferId::svo_shade_direct_diffuse, &shared::PixelLight::directDiffuse},
      {BufferId::svo_shade_direct_specular, &shared::PixelLight::directSpecular},
      {BufferId::svo_shade_indirect_diffuse, &shared::PixelLight::indirectDiffuse},
      {BufferId::svo_shade_indirect_specular, &shared::PixelLight::indirectSpecular}};
  std::vector<std::pair<Buffer, Field>> out;  // the planned terms
  for (const auto& [id, field] : terms)
    if (bufferNeeded(bufferSpec(id), ctx.plan)) out.emplace_back(Buffer(id, extent), field);
  Buffer color(BufferId::svo_shade_color, extent);

  const SvoVolumes tree{o, leaves, &radiance, &mips, nullptr, &trace.lights, nullptr};
  const cone_lanes::TreeBricks laneBricks = treeLaneBricks(tree, cells);
  cone_lanes::Volumes lanes{};
  lanes.n = trace.params.resolution;
  lanes.bricks = &laneBricks;
  // 8x8 tiles, as trace_cones: the tile's shadow and specular cones march together in lanes.
  const tbb::blocked_range2d<int> tiles(0, extent.y, 8, 0, extent.x, 8);
  parallelFor(tiles, [&](const tbb::blocked_range2d<int>& tile) {
    SvoVolumes volumes = tree;  // its tile memo is the task's own
    volumes.leafBricks = &bricks;
    volumes.bricks = &cells;
    std::vector<TilePixel> pixels;
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
        const size_t i = size_t(y) * size_t(extent.x) + size_t(x);
        const uint32_t id = object.get<uint32_t>(i, 0);
        if (id == 0u) {
          color.setVec3(i, background);
          continue;
        }
        pixels.push_back(tilePixel(i, {x, y}, position.vec3At(i), normal.vec3At(i),
                                   trace.objects[id], trace.params));
      }
    // No diffuse cones (treeConeTrace asks for none): the leaves' gathered light stands for them.
    TileTracer tracer(lanes, trace.lights, {}, trace.params);
    tracer.addDirectLight(pixels);
    const std::vector<shared::PixelLight> lights =
        tracer.finish(pixels, tracer.traceDiffuse(pixels));
    for (size_t k = 0; k < pixels.size(); ++k) {
      const size_t i = pixels[k].e;
      const glm::vec3 p = pixels[k].p;
      shared::PixelLight l = lights[k];
      l.indirectDiffuse = tricubic ? shared::svoIrradianceTricubic(volumes, p, depth)
                                   : shared::svoIrradiance(volumes, p, depth);
      for (auto& [buffer, field] : out) buffer.setVec3(i, l.*field);
      color.setVec3(
          i, shared::composePixel(object.get<uint32_t>(i, 0), albedo.vec3At(i), specular.vec3At(i),
                                  emission ? emission->vec3At(i) : glm::vec3(0.0f), l.directDiffuse,
                                  l.directSpecular, l.indirectDiffuse, l.indirectSpecular, 0.0f,
                                  background));
    }
  });
  for (auto& [buffer, field] : out) buffers.put(std::move(buffer));
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
