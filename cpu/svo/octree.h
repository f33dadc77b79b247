// The CPU build of the sparse voxel octree (shaders/shared/svo/svo_layout.h) in its canonical
// form: tiles allocated level by level in Morton order of their keys, so the structure depends on
// the set of samples alone, never on their order or on threads. The GPU allocates with atomics
// in whatever order its threads run; the diff compares both in this form, per key.
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "common/buffer.h"
#include "common/svo/canonical.h"
#include "shaders/shared/svo/build_kernel.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::cpu::svo {

// Which keys of a level have a tile, and each one's rank among them (its index in the level,
// tiles being in key order): a bit per possible key and a running count per 64 keys, so a lookup
// is two reads, where a binary search over 10^5 tiles took 17 dependent ones.
class TileIndex {
 public:
  TileIndex() = default;
  TileIndex(const std::vector<uint32_t>& sortedKeys, uint64_t keySpace);
  // The rank of `key`, or kSvoNull when it has no tile.
  uint32_t rank(uint32_t key) const {
    const uint64_t word = bits_[key >> 6], bit = uint64_t(1) << (key & 63u);
    if ((word & bit) == 0) return 0xffffffffu;
    return before_[key >> 6] + uint32_t(std::popcount(word & (bit - 1)));
  }

 private:
  std::vector<uint64_t> bits_;
  std::vector<uint32_t> before_;
};

struct Octree {
  int depth = 0;
  Words nodes;      // kNodeWords per node, 8 nodes a node tile (levels 1 .. depth-1)
  Words tiles;      // kTileWords per node tile; tile 0 is the root tile
  Words leafTiles;  // kTileWords per leaf tile (level depth)
  // First node tile of each level: levelStart[l] for l = 1 .. depth-1, levelStart[depth] = the
  // node tile count (index 0 unused).
  std::vector<uint32_t> levelStart;
  std::vector<TileIndex> levelIndex;  // each level's tiles by key (index 1 .. depth)

  size_t tileCount() const { return tiles.size() / 4; }
  size_t leafTileCount() const { return leafTiles.size() / 4; }
  // The node tile of `level` (< depth) or leaf tile (level == depth) keyed `key`; kSvoNull if
  // none.
  uint32_t findTile(int level, uint32_t key) const;
  // The same by tile coordinate (node coordinates at level - 1): svoFindTile's answer, from two
  // reads of the level's index where the walk down from the root reads level - 1 node words in a
  // chain. kSvoNull outside the level.
  uint32_t findTileAt(int level, glm::uvec3 tile) const {
    const uint32_t side = 1u << (level - 1);
    if (tile.x >= side || tile.y >= side || tile.z >= side) return shared::kSvoNull;
    return findTile(level, shared::mortonEncode(tile));
  }
};

// Where each sample lands, found in the structure's pass over the samples so that the leaf sums
// need not look again: per sample, the key of its home leaf tile, the tile of its first touched
// leaf on each axis (its other leaves lie in the next tile along an axis); kSvoNull when it
// touches no leaf.
struct SampleHomes {
  std::vector<uint32_t> tileKey;
};

// The tree of depth `depth` over the leaves the samples' RoIs touch, with every ancestor, the
// border tiles the brick boundaries need (docs/svo.md) and the neighbour pointers. Samples outside
// the leaf domain [0, 2^depth)^3 add nothing. Throws InputError naming `source` and
// grid.resolution when the counted tiles would not fit in memory. With `homes`, also where each
// sample landed, for accumulateLeaves.
Octree buildOctree(std::span<const shared::SvoSample> samples, int depth,
                   const std::string& source = "samples", SampleHomes* homes = nullptr);

// The tree of `depth` whose words (canonical order, common/svo/canonical.h) are `words` (its sums
// are not used): build's buffers as the later stages read them.
Octree octreeFromWords(voxgi::svo::OctreeWords words, int depth);

// The fixed-point sums the samples add to the leaves (kSumWords per leaf voxel, 8 per leaf tile
// in local-id order), in units of 1/scale. Throws InputError naming `source` when a leaf's
// opacity sum would pass 2^31 - 1 units. `homes`: buildOctree's for these samples, or null to
// find them again.
Words accumulateLeaves(const Octree& octree, std::span<const shared::SvoSample> samples,
                       float scale, const std::string& source, const SampleHomes* homes = nullptr);

}  // namespace voxgi::cpu::svo
