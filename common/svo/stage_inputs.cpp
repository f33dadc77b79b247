#include "common/svo/stage_inputs.h"

#include <bit>
#include <stdexcept>
#include <string>

#include "common/parallel.h"
#include "shaders/shared/svo/svo_layout.h"
#include "shaders/shared/svo/build_kernel.h"

namespace voxgi::svo {
namespace {

constexpr int kFaces = 6;

// The pyramid of a tree: top level depth - 1, six faces.
void treeParams(shared::ConeTraceParams& params, int depth) {
  params.topLevel = depth - 1;
  params.directional = 1;
}

}  // namespace

void putTree(BufferSet& buffers, OctreeWords words, float weightScale, float emissionScale,
             bool keepSums) {
  const auto put = [&](BufferId id, Words& w) {
    Buffer b(id, glm::ivec3(0, 1, 1));
    b.extent.x = int(w.size() / size_t(b.components()));
    b.words = std::move(w);
    buffers.put(std::move(b));
  };
  buffers.put(leavesBuffer(resolveLeaves(words.sums, weightScale, emissionScale)));
  put(BufferId::svo_build_nodes, words.nodes);
  put(BufferId::svo_build_tiles, words.tiles);
  put(BufferId::svo_build_leaf_tiles, words.leafTiles);
  if (keepSums) put(BufferId::svo_build_leaf_sums, words.sums);
  Buffer scales(BufferId::svo_build_scales, glm::ivec3(1));
  scales.set(0, 0, weightScale);
  scales.set(0, 1, emissionScale);
  buffers.put(std::move(scales));
}

OctreeWords treeWords(const BufferSet& buffers) {
  return {buffers.at(BufferId::svo_build_nodes).words,
          buffers.at(BufferId::svo_build_tiles).words,
          buffers.at(BufferId::svo_build_leaf_tiles).words,
          {}};
}

Leaves resolveLeaves(const Words& sums, float weightScale, float emissionScale) {
  using namespace shared;
  const size_t n = sums.size() / kSumWords;
  Leaves out;
  out.albedo.resize(n);
  out.normal.resize(n);
  out.emission.resize(n);
  const float unit = 1.0f / weightScale;  // a power of two: exact
  parallelFor(size_t(0), n, [&](size_t i) {
    const auto at = [&](int c) { return float(int32_t(sums[i * kSumWords + size_t(c)])) * unit; };
    out.albedo[i] =
        glm::vec4(at(kSumAlbedo), at(kSumAlbedo + 1), at(kSumAlbedo + 2), at(kSumOpacity));
    out.normal[i] = glm::vec3(at(kSumNormal), at(kSumNormal + 1), at(kSumNormal + 2));
    out.emission[i] =
        glm::vec3(at(kSumEmission), at(kSumEmission + 1), at(kSumEmission + 2)) * emissionScale;
  });
  return out;
}

static_assert(kLeafValues == shared::kSumWords, "a leaf value per sum");

Buffer leavesBuffer(const Leaves& leaves) {
  const size_t n = leaves.albedo.size();
  std::vector<float> values(n * kLeafValues);
  parallelFor(size_t(0), n, [&](size_t i) {
    float* v = &values[i * kLeafValues];
    for (int c = 0; c < 3; ++c) {
      v[kLeafAlbedo + c] = leaves.albedo[i][c];
      v[kLeafNormal + c] = leaves.normal[i][c];
      v[kLeafEmission + c] = leaves.emission[i][c];
    }
    v[kLeafOpacity] = leaves.albedo[i].a;
  });
  Buffer b(BufferId::svo_build_leaves, glm::ivec3(int(n), 1, 1));
  floatsToHalves(values, b.words);
  return b;
}

Leaves leavesOf(const Buffer& leaves) {
  const size_t n = leaves.elementCount();
  std::vector<float> values(n * kLeafValues);
  halvesToFloats(leaves.words, values);
  Leaves out;
  out.albedo.resize(n);
  out.normal.resize(n);
  out.emission.resize(n);
  parallelFor(size_t(0), n, [&](size_t i) {
    const float* v = &values[i * kLeafValues];
    const auto vec3At = [&](int at) { return glm::vec3(v[at], v[at + 1], v[at + 2]); };
    out.albedo[i] = glm::vec4(vec3At(kLeafAlbedo), v[kLeafOpacity]);
    out.normal[i] = vec3At(kLeafNormal);
    out.emission[i] = vec3At(kLeafEmission);
  });
  return out;
}

Leaves treeLeaves(const BufferSet& buffers) {
  return leavesOf(buffers.at(BufferId::svo_build_leaves));
}

namespace {

// RGBA values as floats, four a value.
std::span<const float> floatsOf(const std::vector<glm::vec4>& values) {
  return {reinterpret_cast<const float*>(values.data()), values.size() * 4};
}
std::span<float> floatsOf(std::vector<glm::vec4>& values) {
  return {reinterpret_cast<float*>(values.data()), values.size() * 4};
}

}  // namespace

Buffer vec4Buffer(BufferId id, const std::vector<glm::vec4>& values) {
  Buffer b(id, glm::ivec3(int(values.size()), 1, 1));
  floatsToHalves(floatsOf(values), b.words);
  return b;
}

std::vector<glm::vec4> vec4Values(const Buffer& buffer) {
  std::vector<glm::vec4> out(buffer.elementCount());
  halvesToFloats(buffer.words, floatsOf(out));
  return out;
}

// node_faces holds halves (common/svo/stages.inc): a face's RGBA is two words, the nodes' faces
// one after another in canonical order, each level's a contiguous run.
Buffer nodeFacesBuffer(const NodeLevels& levels) {
  size_t nodes = 0;
  for (const auto& level : levels.levels) nodes += level.size() / kFaces;
  Buffer b(BufferId::svo_mip_node_faces, glm::ivec3(int(nodes), 1, 1));
  size_t at = 0;
  for (const auto& level : levels.levels) {
    floatsToHalves(floatsOf(level), std::span(b.words).subspan(at, level.size() * 2));
    at += level.size() * 2;
  }
  return b;
}

NodeLevels nodeLevels(const Buffer& faces, const Words& tiles, int depth) {
  NodeLevels out;
  out.levels.resize(size_t(depth));
  // The tiles come level by level (the canonical order), so each level's faces are one run.
  std::vector<size_t> levelTiles(size_t(depth), 0);
  for (size_t t = 0; t < tiles.size() / shared::kTileWords; ++t)
    ++levelTiles[tiles[t * shared::kTileWords + shared::kTileLevel]];
  size_t total = 0;
  for (const size_t n : levelTiles) total += n;
  if (faces.elementCount() != total * 8)
    throw std::logic_error("svo/mip.node_faces holds " + std::to_string(faces.elementCount()) +
                           " nodes, the tree " + std::to_string(total * 8));
  size_t at = 0;
  for (size_t level = 0; level < levelTiles.size(); ++level) {
    const size_t count = levelTiles[level] * 8 * kFaces;
    out.levels[level].resize(count);
    halvesToFloats(std::span(faces.words).subspan(at, 2 * count), floatsOf(out.levels[level]));
    at += 2 * count;
  }
  return out;
}

FirstStep firstStep(const Settings& settings) {
  return settings.svo.firstStep == SvoFirstStep::ndf ? FirstStep::ndf : FirstStep::plain;
}

ConeTraceSetup treeConeTrace(const StageContext& ctx, int depth) {
  ConeTraceSetup s = prepareConeTrace(ctx);
  treeParams(s.params, depth);
  s.cones.clear();  // no diffuse cones: the leaves hold the diffuse light
  s.params.diffuseConeCount = 0;
  return s;
}

ConeTraceSetup treeGather(const StageContext& ctx, int depth) {
  ConeTraceSetup s = prepareGather(ctx);
  treeParams(s.params, depth);
  return s;
}

}  // namespace voxgi::svo
