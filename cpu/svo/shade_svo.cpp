// CPU shade_svo stage: the gbuffer's pixels lit from the tree (cpu/svo/shade.h).
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/shade.h"

namespace voxgi::cpu {

void svo::shade_svo(const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  checkStageMemory(ctx, StageId::svo_shade_svo);
  const int depth = treeDepth(ctx.scene);
  const Octree o = octreeFromWords(treeWords(buffers, false), depth);
  const Leaves leaves = treeLeaves(buffers);
  const LeafRadiance radiance = vec4Values(buffers.at(BufferId::svo_propagate_svo_radiance));
  const NodeLevels mips = nodeLevels(buffers.at(BufferId::svo_mip_svo_node_faces), o.tiles, depth);
  const ConeTraceSetup trace = treeConeTrace(ctx, depth);
  const PixelShading shading = shadePixels(
      buffers, o, leaves, radiance, mips, buffers.at(BufferId::svo_mip_svo_gathered_bricks).words,
      trace.lights, trace.objects, trace.params, ctx.scene.background,
      ctx.settings.svo.shadeFilter == SvoShadeFilter::tricubic);
  const glm::ivec3 extent = buffers.at(BufferId::common_gbuffer_pixel_position).extent;
  using Field = glm::vec3 shared::PixelLight::*;
  const std::pair<BufferId, Field> terms[] = {
      {BufferId::svo_shade_svo_direct_diffuse, &shared::PixelLight::directDiffuse},
      {BufferId::svo_shade_svo_direct_specular, &shared::PixelLight::directSpecular},
      {BufferId::svo_shade_svo_indirect_diffuse, &shared::PixelLight::indirectDiffuse},
      {BufferId::svo_shade_svo_indirect_specular, &shared::PixelLight::indirectSpecular}};
  for (const auto& [id, field] : terms) {
    if (!bufferNeeded(bufferSpec(id), ctx.plan)) continue;
    Buffer out(id, extent);
    for (size_t e = 0; e < shading.light.size(); ++e) out.setVec3(e, shading.light[e].*field);
    buffers.put(std::move(out));
  }
  Buffer color(BufferId::svo_shade_svo_color, extent);
  for (size_t e = 0; e < shading.color.size(); ++e) color.setVec3(e, shading.color[e]);
  buffers.put(std::move(color));
}

}  // namespace voxgi::cpu
