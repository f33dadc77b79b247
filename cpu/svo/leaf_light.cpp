#include "cpu/svo/leaf_light.h"

#include <bit>

#include <tbb/blocked_range.h>

#include "cpu/vct/gather_lanes.h"
#include "cpu/vct/light_voxel_lanes.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/vct/bounce_kernel.h"
#include "shaders/shared/svo/mip_kernel.h"
#include "shaders/shared/vct/mip_kernel.h"

namespace voxgi::cpu::svo {
namespace {

using shared::kSvoNull;

// The tiles of a node level in tile order: [first, first + count).
std::pair<size_t, size_t> levelRange(const Octree& o, int level) {
  return {o.levelStart[size_t(level)],
          o.levelStart[size_t(level) + 1] - o.levelStart[size_t(level)]};
}

// A leaf's unpremultiplied value: sum / opacity (0 for an empty leaf).
template <class V>
V perOpacity(const V& premultiplied, float opacity) {
  return opacity > 0.0f ? premultiplied / opacity : V(0.0f);
}

// The 8 children of one node for the shared mip kernel: leaves (one value, optionally weighted
// per face by its normal) or a node level's six faces.
struct Children {
  const glm::vec4* values;
  const glm::vec3* normals;  // leaves under FirstStep::ndf, else nullptr
  bool leaves;
  glm::vec4 childAt(int face, glm::ivec3 c) const {
    const int local = c.x + 2 * c.y + 4 * c.z;
    if (!leaves) return values[local * shared::kFaces + face];
    const glm::vec4 v = values[local];
    return normals == nullptr ? v : shared::ndfWeighted(v, normals[local], face);
  }
};

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

NodeLevels mipTree(const Octree& octree, const Leaves& leaves, const LeafRadiance& radiance,
                   FirstStep first) {
  NodeLevels out;
  out.levels.resize(size_t(octree.depth));
  for (int level = octree.depth - 1; level >= 1; --level) {
    const size_t firstTile = levelRange(octree, level).first;
    const size_t count = levelRange(octree, level).second;
    std::vector<glm::vec4>& values = out.levels[size_t(level)];
    values.assign(count * 8 * shared::kFaces, glm::vec4(0.0f));
    const bool fromLeaves = level + 1 == octree.depth;
    parallelFor(size_t(0), count, [&](size_t i) {
      for (size_t local = 0; local < 8; ++local) {
        const size_t node = (firstTile + i) * 8 + local;
        const uint32_t child = octree.nodes[node * shared::kNodeWords + shared::kNodeChild];
        if (child == kSvoNull) continue;
        Children c{};
        c.leaves = fromLeaves;
        if (fromLeaves) {
          c.values = &radiance[size_t(child) * 8];
          c.normals = first == FirstStep::ndf ? &leaves.normal[size_t(child) * 8] : nullptr;
        } else {
          const size_t childRank = child - octree.levelStart[size_t(level) + 1];
          c.values = &out.levels[size_t(level) + 1][childRank * 8 * shared::kFaces];
        }
        for (int face = 0; face < shared::kFaces; ++face)
          values[(i * 8 + local) * shared::kFaces + size_t(face)] =
              shared::roundToHalf4(shared::mipAnisotropic(c, glm::ivec3(0), face));
      }
    });
  }
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
