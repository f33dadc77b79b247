// The sparse voxel octree as the cone library's kernels read it on the GPU
// (shaders/svo/svo_volumes.glsl; the CPU's twin: cpu/svo/svo_volumes.h): the tree's words and the
// leaves' values in GPU buffers, the light pools as RGBA values in two words of halves.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/svo/canonical.h"
#include "common/svo/light_types.h"
#include "gpu/context.h"
#include "gpu/program.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu::svo {

// The octree's words the light passes read (nodes, tile records, leaf tiles) at tree `depth`.
struct Tree {
  const voxgi::svo::OctreeWords& words;
  int depth;
};

template <class T>
GLuint upload(const Gl& gl, const std::vector<T>& v) {
  return createBuffer(gl, v.size() * sizeof(T), v.data());
}

// The light pools hold an RGBA value as two words of halves (shared/half_float.h, packHalves):
// the bytes of `count` such values.
inline size_t halvesBytes(size_t count) {
  return count * sizeof(glm::uvec2);
}

// RGBA values into a pool of halves (each rounded to the nearest; the CPU's values already are).
inline GLuint uploadHalves(const Gl& gl, const std::vector<glm::vec4>& values) {
  std::vector<glm::uvec2> words(values.size());
  for (size_t i = 0; i < values.size(); ++i) words[i] = shared::packHalves(values[i]);
  return upload(gl, words);
}

// `count` values of a pool of halves from value `offset` on, exactly.
inline std::vector<glm::vec4> downloadHalves(const Gl& gl, GLuint buffer, size_t count,
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
struct SvoVolumes {
  GlBuffer nodes, leafTiles, leafValues, source, nodeFaces;
  size_t slots, nodeCount;
  SvoVolumes(const Gl& gl, const Tree& t, const voxgi::svo::Leaves& leaves,
             const voxgi::svo::LeafRadiance* s)
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

}  // namespace voxgi::gpu::svo
