// CPU shade stage: per pixel, trace_cones' direct light with a shadow cone per light and the
// specular cone, read through the tree's bricks (no diffuse cones: the leaves hold the diffuse
// light), plus the leaves' gathered light through their bricks (shaders/shared/svo/shade_kernel.h),
// composed as the dense technique composes (compose_kernel.h). The twin of shaders/svo/shade.comp.
#include "common/gbuffer.h"
#include "common/parallel.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/leaf_light.h"
#include "shaders/shared/vct/compose_kernel.h"
#include "shaders/shared/svo/shade_kernel.h"
#include "shaders/shared/vct/trace_cones_kernel.h"

namespace voxgi::cpu {

void svo::shade(const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  checkStageMemory(ctx, StageId::svo_shade);
  const int depth = treeDepth(ctx.scene);
  const Octree o = octreeFromWords(treeWords(buffers, false), depth);
  const Leaves leaves = treeLeaves(buffers);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_radiance));
  const NodeLevels mips = nodeLevels(buffers.at(BufferId::svo_mip_node_faces), o.tiles, depth);
  const Words& bricks = buffers.at(BufferId::svo_mip_gathered_bricks).words;
  // The cones' trilinear cells from bricks (cpu/svo/leaf_light.h), one tile lookup each.
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

  parallelFor(size_t(0), position.elementCount(), [&](size_t i) {
    const uint32_t id = object.get<uint32_t>(i, 0);
    if (id == 0u) {
      color.setVec3(i, background);
      return;
    }
    SvoVolumes volumes{o, leaves, &radiance, &mips, nullptr, &trace.lights, nullptr};
    volumes.leafBricks = &bricks;
    volumes.bricks = &cells;
    const glm::vec3 p = position.vec3At(i);
    shared::PixelLight l =
        shared::tracePixel(volumes, p, normal.vec3At(i), trace.objects[id], trace.params);
    l.indirectDiffuse = tricubic ? shared::svoIrradianceTricubic(volumes, p, depth)
                                 : shared::svoIrradiance(volumes, p, depth);
    for (auto& [buffer, field] : out) buffer.setVec3(i, l.*field);
    color.setVec3(i, shared::composePixel(id, albedo.vec3At(i), specular.vec3At(i),
                                          emission ? emission->vec3At(i) : glm::vec3(0.0f),
                                          l.directDiffuse, l.directSpecular, l.indirectDiffuse,
                                          l.indirectSpecular, 0.0f, background));
  });
  for (auto& [buffer, field] : out) buffers.put(std::move(buffer));
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
