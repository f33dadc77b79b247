// CPU propagate stage: the leaves' injected light, then propagate.frames progressive bounces
// (cpu/svo/leaf_light.h), from the light the frame before carried under propagate.carry.
#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/leaf_light.h"

namespace voxgi::cpu {

void svo::propagate(const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  const int depth = treeDepth(ctx.scene);
  const SvoSettings& s = ctx.settings.svo;
  const Octree o = octreeFromWords(treeWords(buffers), depth);
  const Leaves leaves = treeLeaves(buffers);
  // Under emitters.mode=area_lights the meshes' emitters are lights and their samples carry no
  // emission (common/svo/samples.h); a point cloud's emission stays in the leaves.
  const std::vector<shared::LightData> lights = sceneLights(ctx.scene, ctx.settings.vct.emitters);
  const LeafRadiance direct =
      injectLeaves(o, leaves, lights, lightVoxelsParams(ctx, int(lights.size()), true));
  const ConeTraceSetup bounce = treeBounce(ctx, depth);
  // In a sequence under propagate.carry, the first frame gathers from the light the frame before
  // left (common/svo/propagate.h).
  const std::optional<CarriedLight> carried = carriedIn(ctx);
  const LeafRadiance start =
      carried ? carriedSource(*carried, o.leafTiles, leaves, direct) : LeafRadiance{};
  FrameOutputs last;
  last.gathered.assign(direct.size(), glm::vec4(0.0f));  // stays so without a frame
  const LeafRadiance radiance = propagateFrames(
      o, leaves, direct, bounce.cones, bounce.params, s.frames, s.clearEachFrame == SvoToggle::on,
      firstStep(ctx.settings), &last, carried ? &start : nullptr);
  carryOut(ctx, o.leafTiles, std::move(last.gatheredStraight));
  buffers.put(vec4Buffer(BufferId::svo_propagate_direct, direct));
  buffers.put(vec4Buffer(BufferId::svo_propagate_radiance, radiance));
  buffers.put(vec4Buffer(BufferId::svo_propagate_gathered, last.gathered));
}

}  // namespace voxgi::cpu
