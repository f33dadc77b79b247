// GPU propagate stage: injection and propagate.frames progressive bounces on the GPU
// (gpu/svo/propagate.h), shaped as cpu/svo/propagate.cpp, from the light the frame before carried
// under propagate.carry; the last frame's gathered light as leaf bricks (gpu/svo/bricks.h) for
// shading.
#include "gpu/svo/propagate.h"

#include <initializer_list>

#include "common/lights.h"
#include "common/svo/propagate.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/stages.h"
#include "gpu/svo/bricks.h"
#include "gpu/svo/mip.h"
#include "gpu/volumes.h"
#include "shaders/shared/cone/mip.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu::svo {
namespace {

using voxgi::svo::LeafRadiance;
using voxgi::svo::NodeLevels;

// Runs `shader` once per leaf slot over the octree's volumes, `blocks` bound from binding 5 on.
void leafPass(const Gl& gl, const Tree& t, const SvoVolumes& v, const ShaderSource& shader,
              std::initializer_list<GLuint> blocks, const char* what) {
  Program program(gl, {&shader});
  program.use();
  program.set("uDepth", t.depth);
  program.set("uCount", unsigned(v.slots));
  v.bind(gl);
  GLuint binding = 5;
  for (const GLuint block : blocks) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding++, block);
  dispatchLinear(gl, v.slots);
  gl.check(what);
}

}  // namespace

LeafRadiance injectLeaves(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                          const std::vector<shared::LightData>& lights,
                          const shared::LightVoxelsParams& params) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  const SvoVolumes v(gl, tree, leaves, nullptr);
  GlBuffer lightBlock(gl, createBlock(gl, params, lights));
  GlBuffer direct(gl, createBuffer(gl, halvesBytes(v.slots), nullptr));
  leafPass(gl, tree, v, shaders::svo_propagate_inject_comp, {lightBlock.get(), direct.get()},
           "propagate_inject");
  return downloadHalves(gl, direct.get(), v.slots);
}

LeafRadiance bounceOnce(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                        const LeafRadiance& direct, const LeafRadiance& source,
                        const std::vector<shared::ConeData>& cones,
                        const shared::ConeTraceParams& params, voxgi::svo::FirstStep first,
                        voxgi::svo::FrameOutputs* outputs) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  SvoVolumes v(gl, tree, leaves, &source);
  NodeLevels mips = mipInto(gl, tree, v, first);
  // Every level as bricks, so that a cone's trilinear cell is one walk and eight texels
  // ([Salm 2015, §4.4]), as on the CPU.
  GlBuffer tiles(gl, createBuffer(gl, tree.words.tiles.size() * 4, tree.words.tiles.data()));
  GlBuffer leafBricks(
      gl, completeBricks(gl, v.nodes.get(), v.leafTiles.get(), v.source.get(), v.slots / 8, 1));
  GlBuffer nodeBricks(gl, completeBricks(gl, v.nodes.get(), tiles.get(), v.nodeFaces.get(),
                                         v.nodeCount / 8, shared::kFaces));
  // The cones read the bricks alone (VOXGI_BRICK_CELLS): the faces and the source they repeat
  // go before the gather's own pools are allocated, as [Salm 2015]'s pools are bricks alone.
  v.source = GlBuffer(gl, 0);
  v.nodeFaces = GlBuffer(gl, 0);
  GlBuffer coneBlock(gl, createBlock(gl, params, cones));
  GlBuffer directBlock(gl, uploadHalves(gl, direct));
  GlBuffer frame(gl, createBuffer(gl, halvesBytes(2 * v.slots), nullptr));
  leafPass(gl, tree, v, shaders::svo_propagate_gather_comp,
           {coneBlock.get(), directBlock.get(), frame.get(), leafBricks.get(), nodeBricks.get()},
           "propagate_gather");
  const std::vector<glm::vec4> both = downloadHalves(gl, frame.get(), 2 * v.slots);
  LeafRadiance next(v.slots), gathered(v.slots);
  std::vector<glm::vec3> straight(v.slots);
  for (size_t s = 0; s < v.slots; ++s) {
    next[s] = both[2 * s];
    const glm::vec4 g = both[2 * s + 1];
    // The CPU's product of the stored halves, rounded as the pool stores it.
    gathered[s] = shared::roundToHalf4(glm::vec4(glm::vec3(g) * g.a, g.a));
    straight[s] = glm::vec3(g);
  }
  if (outputs != nullptr) *outputs = {std::move(mips), std::move(gathered), std::move(straight)};
  return next;
}

LeafRadiance propagateFrames(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                             const LeafRadiance& direct, const std::vector<shared::ConeData>& cones,
                             const shared::ConeTraceParams& params, int frames, bool clearEachFrame,
                             voxgi::svo::FirstStep first, voxgi::svo::FrameOutputs* outputs,
                             const LeafRadiance* start) {
  LeafRadiance current = start != nullptr ? *start : direct;
  for (int frame = 0; frame < frames; ++frame)
    current = bounceOnce(context, tree, leaves, direct, clearEachFrame ? direct : current, cones,
                         params, first, frame + 1 == frames ? outputs : nullptr);
  return current;
}

}  // namespace voxgi::gpu::svo

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
  const ConeTraceSetup gather = treeGather(ctx, depth);
  // In a sequence under propagate.carry, the first frame gathers from the light the frame before
  // left (common/svo/propagate.h).
  const std::optional<CarriedLight> carried = carriedIn(ctx);
  const LeafRadiance start =
      carried ? carriedSource(*carried, words.leafTiles, leaves, direct) : LeafRadiance{};
  FrameOutputs last;
  last.gathered.assign(direct.size(), glm::vec4(0.0f));  // stays so without a frame
  const LeafRadiance radiance =
      propagateFrames(context, tree, leaves, direct, gather.cones, gather.params, s.frames,
                      s.clearEachFrame == SvoToggle::on, firstStep(ctx.settings), &last,
                      carried ? &start : nullptr);
  carryOut(ctx, words.leafTiles, std::move(last.gatheredStraight));
  Buffer gathered = vec4Buffer(BufferId::svo_propagate_gathered, last.gathered);
  const size_t tiles = words.leafTiles.size() / shared::kTileWords;
  GlBuffer nodes(gl, createBuffer(gl, words.nodes.size() * 4, words.nodes.data()));
  GlBuffer leafTiles(gl, createBuffer(gl, words.leafTiles.size() * 4, words.leafTiles.data()));
  GlBuffer interior(gl, uploadWords(gl, gathered));  // halves, as the pools hold them
  GlBuffer bricks(gl,
                  svo::completeBricks(gl, nodes.get(), leafTiles.get(), interior.get(), tiles, 1));
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
