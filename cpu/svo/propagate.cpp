// CPU propagate stage: the leaves' injected light, then propagate.frames progressive bounces
// (cpu/svo/propagate.h), from the light the frame before carried under propagate.carry; the last
// frame's gathered light as leaf bricks (cpu/svo/bricks.h, completeBricks) for shading.
#include "cpu/svo/propagate.h"

#include <tbb/blocked_range.h>

#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "cpu/stages.h"
#include "cpu/svo/bricks.h"
#include "cpu/svo/mip.h"
#include "cpu/svo/svo_volumes.h"
#include "cpu/cone/gather_lanes.h"
#include "cpu/cone/voxel_light_lanes.h"
#include "shaders/shared/cone/gather.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::cpu::svo {
namespace {

// The real leaves of a range of leaf tiles (forEachRealLeaf), for a batch kernel.
struct RealLeaves {
  std::vector<size_t> slots;
  std::vector<glm::ivec3> voxels;
};
RealLeaves realLeaves(const Octree& octree, const tbb::blocked_range<size_t>& tiles) {
  RealLeaves r;
  forEachRealLeaf(octree, tiles, [&](size_t slot, glm::ivec3 v) {
    r.slots.push_back(slot);
    r.voxels.push_back(v);
  });
  return r;
}

}  // namespace

LeafRadiance injectLeaves(const Octree& octree, const Leaves& leaves,
                          const std::vector<shared::LightData>& lights,
                          const shared::LightVoxelsParams& params, SimdLevel level) {
  LeafRadiance out(octree.leafTileCount() * 8, glm::vec4(0.0f));
  const std::vector<uint32_t> opaque = opaqueLeaves(octree, leaves);
  const SvoVolumes tree{octree, leaves, nullptr, nullptr, nullptr, &lights};
  // Without a map covering the kernel's grid, each leaf is lit by the kernel itself.
  const bool lanes = !opaque.empty() && params.resolution == 1 << octree.depth;
  // Leaf tiles a task: a few thousand rays, enough to keep every lane busy.
  parallelFor(tbb::blocked_range<size_t>(0, octree.leafTileCount(), 64), [&](const auto& range) {
    SvoVolumes volumes = tree;  // its tile memo is the task's own
    if (!opaque.empty()) volumes.opaque = &opaque;
    const ShadowRays<SvoVolumes> rays{&volumes, &params};
    const RealLeaves real = realLeaves(octree, range);
    std::vector<glm::vec4> lit(real.voxels.size());
    if (lanes)
      lightVoxels(level, volumes, rays.volume(opaque.data()), real.voxels, params, lit);
    else
      for (size_t i = 0; i < lit.size(); ++i)
        lit[i] = shared::lightVoxel(volumes, real.voxels[i], params);
    for (size_t i = 0; i < lit.size(); ++i) out[real.slots[i]] = shared::roundToHalf4(lit[i]);
  });
  return out;
}

LeafRadiance bounceOnce(const Octree& octree, const Leaves& leaves, const LeafRadiance& direct,
                        const LeafRadiance& source, const std::vector<shared::ConeData>& cones,
                        const shared::ConeTraceParams& params, FirstStep first,
                        FrameOutputs* outputs) {
  NodeLevels mips = mipTree(octree, leaves, source, first);
  const TreeBricks bricks = treeBricks(octree, source, mips);
  const SvoVolumes tree{octree, leaves, &source, &mips, &direct, nullptr, &cones};
  const cone_lanes::TreeBricks laneBricks = treeLaneBricks(tree, bricks);
  cone_lanes::Volumes lanes{};
  lanes.n = params.resolution;
  lanes.bricks = &laneBricks;
  LeafRadiance next(source.size(), glm::vec4(0.0f));
  const size_t kept = outputs != nullptr ? source.size() : 0;
  LeafRadiance gathered(kept, glm::vec4(0.0f));
  std::vector<glm::vec3> straight(kept, glm::vec3(0.0f));
  // Leaf tiles a task: a few thousand cones, enough to keep every lane busy.
  const tbb::blocked_range<size_t> tiles(0, octree.leafTileCount(), 64);
  parallelFor(tiles, [&](const tbb::blocked_range<size_t>& range) {
    SvoVolumes volumes = tree;  // its tile memo is the task's own
    const RealLeaves real = realLeaves(octree, range);
    const std::vector<size_t>& slots = real.slots;
    const std::vector<glm::ivec3>& voxels = real.voxels;
    std::vector<glm::vec3> g(voxels.size());
    gatherVoxels(simdLevel(), volumes, lanes, voxels, params, g);
    for (size_t i = 0; i < slots.size(); ++i) {
      const size_t slot = slots[i];
      // The gathered light as its pool stores it (halves), and the radiance reflected from that,
      // as a sequence under propagate.carry reflects the stored light (carriedSource).
      const glm::vec4 stored = shared::roundToHalf4(glm::vec4(g[i], direct[slot].a));
      next[slot] = shared::roundToHalf4(
          shared::addReflected(direct[slot], volumes.albedoAt(voxels[i]), glm::vec3(stored)));
      if (outputs == nullptr) continue;
      straight[slot] = glm::vec3(stored);
      gathered[slot] = shared::roundToHalf4(glm::vec4(glm::vec3(stored) * stored.a, stored.a));
    }
  });
  if (outputs != nullptr) *outputs = {std::move(mips), std::move(gathered), std::move(straight)};
  return next;
}

LeafRadiance propagateFrames(const Octree& octree, const Leaves& leaves, const LeafRadiance& direct,
                             const std::vector<shared::ConeData>& cones,
                             const shared::ConeTraceParams& params, int frames, bool clearEachFrame,
                             FirstStep first, FrameOutputs* outputs, const LeafRadiance* start) {
  LeafRadiance current = start != nullptr ? *start : direct;
  for (int frame = 0; frame < frames; ++frame)
    current = bounceOnce(octree, leaves, direct, clearEachFrame ? direct : current, cones, params,
                         first, frame + 1 == frames ? outputs : nullptr);
  return current;
}

}  // namespace voxgi::cpu::svo

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
  const ConeTraceSetup gather = treeGather(ctx, depth);
  // In a sequence under propagate.carry, the first frame gathers from the light the frame before
  // left (common/svo/propagate.h).
  const std::optional<CarriedLight> carried = carriedIn(ctx);
  const LeafRadiance start =
      carried ? carriedSource(*carried, o.leafTiles, leaves, direct) : LeafRadiance{};
  FrameOutputs last;
  last.gathered.assign(direct.size(), glm::vec4(0.0f));  // stays so without a frame
  const LeafRadiance radiance = propagateFrames(
      o, leaves, direct, gather.cones, gather.params, s.frames, s.clearEachFrame == SvoToggle::on,
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
