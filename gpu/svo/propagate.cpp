// GPU propagate stage: injection and propagate.frames progressive bounces on the GPU
// (gpu/svo/leaf_light.h), frame by frame as cpu/svo/leaf_light.cpp's propagateFrames, from the
// light the frame before carried under propagate.carry. The leaf
// sums are decoded on the host (common/svo/stage_inputs.h: exact power-of-two scaling, the same
// floats the CPU decodes).
#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "gpu/svo/leaf_light.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void svo::propagate(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  beginStage(context, ctx, StageId::svo_propagate);
  const int depth = treeDepth(ctx.scene);
  const SvoSettings& s = ctx.settings.svo;
  const OctreeWords words = treeWords(buffers);
  const Tree tree{words, depth};
  const Leaves leaves = treeLeaves(buffers);
  // Under emitters.mode=area_lights the meshes' emitters are lights and their samples carry no
  // emission (common/svo/samples.h); a point cloud's emission stays in the leaves.
  const std::vector<shared::LightData> lights = sceneLights(ctx.scene, ctx.settings.vct.emitters);
  const LeafRadiance direct =
      injectLeaves(context, tree, leaves, lights, lightVoxelsParams(ctx, int(lights.size()), true));
  const ConeTraceSetup bounce = treeBounce(ctx, depth);
  const FirstStep first = firstStep(ctx.settings);
  FrameOutputs last;
  last.gathered.assign(direct.size(), glm::vec4(0.0f));  // stays so without a frame
  // In a sequence under propagate.carry, the first frame gathers from the light the frame before
  // left (common/svo/propagate.h).
  const std::optional<CarriedLight> carried = carriedIn(ctx);
  LeafRadiance radiance =
      carried ? carriedSource(*carried, words.leafTiles, leaves, direct) : direct;
  for (int frame = 0; frame < s.frames; ++frame)
    radiance = bounceOnce(context, tree, leaves, direct,
                          s.clearEachFrame == SvoToggle::on ? direct : radiance, bounce.cones,
                          bounce.params, first, frame + 1 == s.frames ? &last : nullptr);
  carryOut(ctx, words.leafTiles, std::move(last.gatheredStraight));
  buffers.put(vec4Buffer(BufferId::svo_propagate_direct, direct));
  buffers.put(vec4Buffer(BufferId::svo_propagate_radiance, radiance));
  buffers.put(vec4Buffer(BufferId::svo_propagate_gathered, last.gathered));
}

}  // namespace voxgi::gpu
