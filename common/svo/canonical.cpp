#include "common/svo/canonical.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "shaders/shared/svo/build_kernel.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::svo {
namespace {

using shared::kSvoNull;
using shared::kTileWords;

// The permutation old -> new that sorts tile records by (level, key).
std::vector<uint32_t> sortingPermutation(const Words& tiles) {
  const size_t count = tiles.size() / kTileWords;
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  const auto field = [&](uint32_t t, int f) { return tiles[size_t(t) * kTileWords + size_t(f)]; };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return std::pair(field(a, shared::kTileLevel), field(a, shared::kTileKey)) <
           std::pair(field(b, shared::kTileLevel), field(b, shared::kTileKey));
  });
  std::vector<uint32_t> rank(count);
  for (uint32_t r = 0; r < count; ++r) rank[order[r]] = r;
  return rank;
}

// Tile records moved to their new places, parents renumbered.
Words moveTiles(const Words& tiles, const std::vector<uint32_t>& rank,
                const std::vector<uint32_t>& nodeTileRank) {
  Words out(tiles.size());
  for (size_t t = 0; t < rank.size(); ++t)
    for (int f = 0; f < kTileWords; ++f) {
      uint32_t w = tiles[t * kTileWords + size_t(f)];
      if (f == shared::kTileParent && w != kSvoNull) w = nodeTileRank[w / 8] * 8 + w % 8;
      out[size_t(rank[t]) * kTileWords + size_t(f)] = w;
    }
  return out;
}

}  // namespace

void canonicalize(OctreeWords& o, int depth) {
  using namespace shared;
  const std::vector<uint32_t> nodeRank = sortingPermutation(o.tiles);
  const std::vector<uint32_t> leafRank = sortingPermutation(o.leafTiles);
  const auto node = [&](uint32_t n) { return n == kSvoNull ? n : nodeRank[n / 8] * 8 + n % 8; };
  Words nodes(o.nodes.size());
  for (size_t t = 0; t < nodeRank.size(); ++t) {
    const bool leafParents = o.tiles[t * kTileWords + kTileLevel] == uint32_t(depth - 1);
    for (size_t local = 0; local < 8; ++local) {
      const uint32_t* from = &o.nodes[(t * 8 + local) * kNodeWords];
      uint32_t* to = &nodes[(size_t(nodeRank[t]) * 8 + local) * kNodeWords];
      const uint32_t child = from[kNodeChild];
      to[kNodeChild] = child == kSvoNull ? child : leafParents ? leafRank[child] : nodeRank[child];
      for (int f = 0; f < 6; ++f) to[kNodeNeighbour + f] = node(from[kNodeNeighbour + f]);
      to[kNodeFlags] = from[kNodeFlags];
    }
  }
  Words tiles = moveTiles(o.tiles, nodeRank, nodeRank);
  Words leafTiles = moveTiles(o.leafTiles, leafRank, nodeRank);
  if (!o.sums.empty()) {
    Words sums(o.sums.size());
    const size_t block = 8 * size_t(kSumWords);
    for (size_t t = 0; t < leafRank.size(); ++t)
      std::copy_n(o.sums.begin() + ptrdiff_t(t * block), block,
                  sums.begin() + ptrdiff_t(size_t(leafRank[t]) * block));
    o.sums = std::move(sums);
  }
  o.nodes = std::move(nodes);
  o.tiles = std::move(tiles);
  o.leafTiles = std::move(leafTiles);
}

}  // namespace voxgi::svo
