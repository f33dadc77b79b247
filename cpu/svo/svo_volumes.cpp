#include "cpu/svo/svo_volumes.h"

#include <bit>

#include <tbb/blocked_range.h>

#include "shaders/shared/cone/mip.h"

namespace voxgi::cpu::svo {
namespace {

using shared::kSvoNull;

// A leaf's unpremultiplied value: sum / opacity (0 for an empty leaf).
template <class V>
V perOpacity(const V& premultiplied, float opacity) {
  return opacity > 0.0f ? premultiplied / opacity : V(0.0f);
}

}  // namespace

uint32_t SvoVolumes::tileAt(int level, glm::uvec3 tile) const {
  if (level == memoLevel && tile == memoTile) return memoIndex;
  const uint32_t t = octree.findTileAt(level, tile);
  memoLevel = level, memoTile = tile, memoIndex = t;
  return t;
}

int64_t SvoVolumes::slot(int level, glm::ivec3 v) const {
  const uint32_t t = tileAt(level, glm::uvec3(v >> 1));
  if (t == kSvoNull) return -1;
  const size_t first = level == octree.depth ? 0 : octree.levelStart[size_t(level)];
  return int64_t((t - first) * 8 + shared::localId(glm::uvec3(v)));
}

float SvoVolumes::leafOpacity(glm::ivec3 v) const {
  const int64_t s = slot(octree.depth, v);
  return s < 0 ? 0.0f : std::min(leaves.albedo[size_t(s)].a, 1.0f);
}

glm::vec3 SvoVolumes::albedoAt(glm::ivec3 v) const {
  const int64_t s = slot(octree.depth, v);
  if (s < 0) return glm::vec3(0.0f);
  const glm::vec4 a = leaves.albedo[size_t(s)];
  return perOpacity(glm::vec3(a), a.a);
}

glm::vec3 SvoVolumes::normalAt(glm::ivec3 v) const {
  const int64_t s = slot(octree.depth, v);
  return s < 0 ? glm::vec3(0.0f) : leaves.normal[size_t(s)];
}

glm::vec3 SvoVolumes::emissionAt(glm::ivec3 v) const {
  const int64_t s = slot(octree.depth, v);
  return s < 0 ? glm::vec3(0.0f)
               : perOpacity(leaves.emission[size_t(s)], leaves.albedo[size_t(s)].a);
}

glm::vec4 SvoVolumes::directAt(glm::ivec3 v) const {
  const int64_t s = slot(octree.depth, v);
  return s < 0 ? glm::vec4(0.0f) : (*direct)[size_t(s)];
}

glm::vec4 SvoVolumes::pyramidAt(int level, int face, glm::ivec3 v) const {
  const int tree = octree.depth - level;
  const int64_t s = slot(tree, v);
  if (s < 0) return glm::vec4(0.0f);
  if (level == 0) return (*radiance)[size_t(s)];
  return nodes->levels[size_t(tree)][size_t(s) * shared::kFaces + size_t(face)];
}

bool SvoVolumes::filterBrickCell(int level, int face, const shared::TrilinearCell& c,
                                 glm::vec4& out) const {
  if (bricks == nullptr) return false;
  const int tree = octree.depth - level;
  const glm::ivec3 t = glm::max(c.base, glm::ivec3(0)) >> 1;
  const uint32_t tile = tileAt(tree, glm::uvec3(t));
  if (tile == kSvoNull) {
    out = glm::vec4(0.0f);  // eight zero taps blend to +0
    return true;
  }
  const bool leafLevel = tree == octree.depth;
  const size_t first = leafLevel ? 0 : octree.levelStart[size_t(tree)];
  const size_t faces = leafLevel ? 1 : size_t(shared::kFaces);
  const size_t f = leafLevel ? 0 : size_t(face);
  const glm::vec4* brick =
      bricks->levels[size_t(tree)].data() + (tile - first) * shared::kBrickTexels * faces;
  const glm::ivec3 o = c.base - t * 2;
  const auto texel = [&](int dx, int dy, int dz) {
    const glm::ivec3 q = o + glm::ivec3(dx, dy, dz);
    if (q.x < 0 || q.y < 0 || q.z < 0) return glm::vec4(0.0f);  // left of the grid
    return brick[shared::brickTexel(q) * faces + f];
  };
  out = shared::blendCell(texel(0, 0, 0), texel(1, 0, 0), texel(0, 1, 0), texel(1, 1, 0),
                          texel(0, 0, 1), texel(1, 0, 1), texel(0, 1, 1), texel(1, 1, 1), c.f);
  return true;
}

namespace {

// TreeBricks::findTile for the lanes: the levels' tile indices, which every task may share.
uint32_t findLaneTile(const void* tree, int level, uint32_t x, uint32_t y, uint32_t z) {
  const Octree& o = static_cast<const SvoVolumes*>(tree)->octree;
  return o.findTileAt(o.depth - level, glm::uvec3(x, y, z));
}

}  // namespace

cone_lanes::TreeBricks treeLaneBricks(const SvoVolumes& tree, const TreeBricks& bricks) {
  const Octree& o = tree.octree;
  cone_lanes::TreeBricks b{};
  // Pyramid level l is tree level depth - l; the cones stop below the root (topLevel = depth - 1).
  for (int level = 0; level < o.depth; ++level) {
    const int t = o.depth - level;
    b.levels[level] = reinterpret_cast<const uint32_t*>(bricks.levels[size_t(t)].data());
    b.firstTile[level] = level == 0 ? 0u : o.levelStart[size_t(t)];
    b.faces[level] = level == 0 ? 1 : shared::kFaces;
  }
  b.findTile = findLaneTile;
  b.tree = &tree;
  return b;
}

TreeBricks treeBricks(const Octree& octree, const LeafRadiance& radiance, const NodeLevels& mips) {
  TreeBricks b;
  b.levels.resize(size_t(octree.depth) + 1);
  using Values = std::vector<glm::vec4>;
  b.levels[size_t(octree.depth)] =
      completeBricks<Values>(octree, octree.depth, std::span<const glm::vec4>(radiance), 1);
  for (int level = 1; level < octree.depth; ++level)
    b.levels[size_t(level)] = completeBricks<Values>(
        octree, level, std::span<const glm::vec4>(mips.levels[size_t(level)]), shared::kFaces);
  return b;
}

std::vector<uint32_t> opaqueLeaves(const Octree& octree, const Leaves& leaves) {
  if (octree.depth > 9) return {};
  // A tile's eight leaves are bits 8 key .. 8 key + 7, the byte of its key in the words' memory
  // (little-endian), written by the tile's task alone; every leaf counts, with samples or only
  // touched by a neighbour's.
  static_assert(std::endian::native == std::endian::little);
  const size_t tiles = size_t(1) << (3 * (octree.depth - 1));
  std::vector<uint32_t> words((tiles + 3) / 4, 0u);
  uint8_t* bytes = reinterpret_cast<uint8_t*>(words.data());
  parallelFor(size_t(0), octree.leafTileCount(), [&](size_t t) {
    const uint32_t key = octree.leafTiles[t * shared::kTileWords + shared::kTileKey];
    uint8_t byte = 0;
    for (uint32_t local = 0; local < 8; ++local)
      if (leaves.albedo[t * 8 + local].a > 0.0f) byte = uint8_t(byte | (1u << local));
    bytes[key] = byte;
  });
  return words;
}

}  // namespace voxgi::cpu::svo
