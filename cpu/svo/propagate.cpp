// CPU propagate stage: the leaves' injected light, then propagate.frames progressive bounces
// (cpu/svo/leaf_light.h), from the light the frame before carried under propagate.carry; the last
// frame's gathered light as leaf bricks (cpu/svo/octree.h, completeBricks) for shading.
#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/leaf_light.h"
#include "shaders/shared/svo/svo_layout.h"

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
  Buffer gathered = vec4Buffer(BufferId::svo_propagate_gathered, last.gathered);
  Buffer bricks(BufferId::svo_propagate_gathered_bricks,
                glm::ivec3(int(o.leafTileCount()) * shared::kBrickTexels, 1, 1));
  // A brick's texels are copies of the leaves' values, so the packed halves copy as they are.
  bricks.words = completeBricks(o, depth, gathered.words, int(gathered.elementWords()));
  buffers.put(std::move(bricks));
  buffers.put(vec4Buffer(BufferId::svo_propagate_radiance, radiance));
  // The bricks hold the gathered light; the per-leaf light is kept only to be compared.
  if (ctx.plan.on(Effect::leaf_light)) {
    buffers.put(vec4Buffer(BufferId::svo_propagate_direct, direct));
    buffers.put(std::move(gathered));
  }
}

}  // namespace voxgi::cpu
