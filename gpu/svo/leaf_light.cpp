#include "gpu/svo/leaf_light.h"

#include <algorithm>
#include <initializer_list>

#include "gpu/program.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"
#include "shaders/shared/vct/mip_kernel.h"

namespace voxgi::gpu::svo {
namespace {

using voxgi::svo::LeafRadiance;
using voxgi::svo::NodeLevels;

template <class T>
GLuint upload(const Gl& gl, const std::vector<T>& v) {
  return createBuffer(gl, v.size() * sizeof(T), v.data());
}

// The light pools hold an RGBA value as two words of halves (shared/half_float.h, packHalves):
// the bytes of `count` such values.
size_t halvesBytes(size_t count) {
  return count * sizeof(glm::uvec2);
}

// RGBA values into a pool of halves (each rounded to the nearest; the CPU's values already are).
GLuint uploadHalves(const Gl& gl, const std::vector<glm::vec4>& values) {
  std::vector<glm::uvec2> words(values.size());
  for (size_t i = 0; i < values.size(); ++i) words[i] = shared::packHalves(values[i]);
  return upload(gl, words);
}

// `count` values of a pool of halves from value `offset` on, exactly.
std::vector<glm::vec4> downloadHalves(const Gl& gl, GLuint buffer, size_t count,
                                      size_t offset = 0) {
  std::vector<glm::uvec2> words(count);
  if (count > 0)
    gl.GetNamedBufferSubData(buffer, GLintptr(halvesBytes(offset)), GLsizeiptr(halvesBytes(count)),
                             words.data());
  std::vector<glm::vec4> out(count);
  for (size_t i = 0; i < count; ++i) out[i] = shared::unpackHalves(words[i]);
  return out;
}

// The octree and the leaves as svo_volumes.glsl reads them: node words, leaf tiles, leaf values
// (albedo, normal, emission: three RGBA a leaf slot), level 0's radiance and the node faces, the
// values in halves (build's leaves are halves already, so their packing is exact).
struct Volumes {
  GlBuffer nodes, leafTiles, leafValues, source, nodeFaces;
  size_t slots, nodeCount;
  Volumes(const Gl& gl, const Tree& t, const voxgi::svo::Leaves& leaves, const LeafRadiance* s)
      : nodes(gl, createBuffer(gl, t.words.nodes.size() * 4, t.words.nodes.data())),
        leafTiles(gl, createBuffer(gl, t.words.leafTiles.size() * 4, t.words.leafTiles.data())),
        leafValues(gl, 0),
        source(gl, 0),
        nodeFaces(gl, 0),
        slots(leaves.albedo.size()),
        nodeCount(t.words.nodes.size() / shared::kNodeWords) {
    std::vector<glm::vec4> values(3 * slots);
    for (size_t i = 0; i < slots; ++i) {
      values[3 * i] = leaves.albedo[i];
      values[3 * i + 1] = glm::vec4(leaves.normal[i], 0.0f);
      values[3 * i + 2] = glm::vec4(leaves.emission[i], 0.0f);
    }
    leafValues = GlBuffer(gl, uploadHalves(gl, values));
    source = GlBuffer(gl, s != nullptr ? uploadHalves(gl, *s) : createBuffer(gl, 16, nullptr));
    nodeFaces = GlBuffer(gl, createBuffer(gl, halvesBytes(nodeCount * 6), nullptr));
  }
  void bind(const Gl& gl) const {
    const GLuint blocks[5] = {nodes.get(), leafTiles.get(), leafValues.get(), source.get(),
                              nodeFaces.get()};
    for (GLuint b = 0; b < 5; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  }
};

// Node tiles per level: tiles [start[l], start[l + 1]) are level l's (the canonical order).
std::vector<uint32_t> levelStarts(const Tree& t) {
  std::vector<uint32_t> start(size_t(t.depth) + 1, 0);
  const size_t tiles = t.words.tiles.size() / shared::kTileWords;
  uint32_t s = 0;
  for (int l = 1; l <= t.depth; ++l) {
    while (s < tiles && t.words.tiles[s * shared::kTileWords + shared::kTileLevel] < uint32_t(l))
      ++s;
    start[size_t(l)] = s;
  }
  return start;
}

// Fills v.nodeFaces from `first`'s leaves up to the root tile; returns them per level.
NodeLevels mipInto(const Gl& gl, const Tree& t, const Volumes& v, voxgi::svo::FirstStep first) {
  Program program(gl, {&shaders::svo_mip_comp});
  program.use();
  program.set("uDepth", t.depth);
  program.set("uNdfWeights", first == voxgi::svo::FirstStep::ndf ? 1 : 0);
  v.bind(gl);
  const std::vector<uint32_t> start = levelStarts(t);
  NodeLevels out;
  out.levels.resize(size_t(t.depth));
  for (int level = t.depth - 1; level >= 1; --level) {
    const uint32_t tiles = start[size_t(level) + 1] - start[size_t(level)];
    program.set("uLevel", level);
    program.set("uFirst", start[size_t(level)] * 8u);
    program.set("uCount", tiles * 8u);
    dispatchLinear(gl, size_t(tiles) * 8);
    out.levels[size_t(level)] = downloadHalves(gl, v.nodeFaces.get(), size_t(tiles) * 8 * 6,
                                               size_t(start[size_t(level)]) * 8 * 6);
  }
  gl.check("mip");
  return out;
}

// Runs `shader` once per leaf slot over the octree's volumes, `blocks` bound from binding 5 on.
void leafPass(const Gl& gl, const Tree& t, const Volumes& v, const ShaderSource& shader,
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

GLuint buildBricks(const Gl& gl, GLuint nodes, GLuint tileRecords, GLuint interior,
                   size_t tileCount, int faces) {
  const size_t texels = tileCount * shared::kBrickTexels;
  const GLuint bricks =
      createBuffer(gl, halvesBytes(std::max<size_t>(texels, 1) * size_t(faces)), nullptr);
  Program program(gl, {&shaders::svo_mip_brick_comp});
  program.use();
  program.set("uCount", unsigned(texels));
  program.set("uFaces", unsigned(faces));
  const GLuint blocks[] = {nodes, tileRecords, interior, bricks};
  for (GLuint b = 0; b < 4; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  dispatchLinear(gl, texels);
  gl.check("bricks");
  return bricks;
}

LeafRadiance injectLeaves(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                          const std::vector<shared::LightData>& lights,
                          const shared::LightVoxelsParams& params) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  const Volumes v(gl, tree, leaves, nullptr);
  GlBuffer lightBlock(gl, createBlock(gl, params, lights));
  GlBuffer direct(gl, createBuffer(gl, halvesBytes(v.slots), nullptr));
  leafPass(gl, tree, v, shaders::svo_propagate_inject_comp, {lightBlock.get(), direct.get()},
           "propagate_inject");
  return downloadHalves(gl, direct.get(), v.slots);
}

NodeLevels mipTree(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                   const LeafRadiance& radiance, voxgi::svo::FirstStep first) {
  context.makeCurrent();
  const Volumes v(context.gl(), tree, leaves, &radiance);
  return mipInto(context.gl(), tree, v, first);
}

LeafRadiance bounceOnce(GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
                        const LeafRadiance& direct, const LeafRadiance& source,
                        const std::vector<shared::ConeData>& cones,
                        const shared::ConeTraceParams& params, voxgi::svo::FirstStep first,
                        voxgi::svo::FrameOutputs* outputs) {
  context.makeCurrent();
  const Gl& gl = context.gl();
  Volumes v(gl, tree, leaves, &source);
  NodeLevels mips = mipInto(gl, tree, v, first);
  // Every level as bricks, so that a cone's trilinear cell is one walk and eight texels
  // ([Salm 2015, §4.4]), as on the CPU.
  GlBuffer tiles(gl, createBuffer(gl, tree.words.tiles.size() * 4, tree.words.tiles.data()));
  GlBuffer leafBricks(
      gl, buildBricks(gl, v.nodes.get(), v.leafTiles.get(), v.source.get(), v.slots / 8, 1));
  GlBuffer nodeBricks(gl, buildBricks(gl, v.nodes.get(), tiles.get(), v.nodeFaces.get(),
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

}  // namespace voxgi::gpu::svo
