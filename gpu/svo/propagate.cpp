// GPU propagate stage: injection and propagate.frames progressive bounces on the GPU
// (gpu/svo/leaf_light.h), frame by frame as cpu/svo/leaf_light.cpp's propagateFrames, from the
// light the frame before carried under propagate.carry; the last frame's gathered light as leaf
// bricks (shaders/svo/mip_brick.comp) for shading.
#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "gpu/svo/leaf_light.h"
#include "gpu/volumes.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu {

void svo::propagate(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  const Gl& gl = beginStage(context, ctx, StageId::svo_propagate);
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
  Buffer gathered = vec4Buffer(BufferId::svo_propagate_gathered, last.gathered);
  const size_t tiles = words.leafTiles.size() / shared::kTileWords;
  GlBuffer nodes(gl, createBuffer(gl, words.nodes.size() * 4, words.nodes.data()));
  GlBuffer leafTiles(gl, createBuffer(gl, words.leafTiles.size() * 4, words.leafTiles.data()));
  GlBuffer interior(gl, uploadWords(gl, gathered));  // halves, as the pools hold them
  GlBuffer bricks(gl, svo::buildBricks(gl, nodes.get(), leafTiles.get(), interior.get(), tiles, 1));
  Buffer out(BufferId::svo_propagate_gathered_bricks,
             glm::ivec3(int(tiles * shared::kBrickTexels), 1, 1));
  readWords(gl, bricks.get(), out);
  buffers.put(std::move(out));
  buffers.put(vec4Buffer(BufferId::svo_propagate_radiance, radiance));
  // The bricks hold the gathered light; the per-leaf light is kept only to be compared.
  if (ctx.plan.on(Effect::leaf_light)) {
    buffers.put(vec4Buffer(BufferId::svo_propagate_direct, direct));
    buffers.put(std::move(gathered));
  }
}

}  // namespace voxgi::gpu
