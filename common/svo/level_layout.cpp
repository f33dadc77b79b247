#include "common/svo/level_layout.h"

#include <bit>

#include "common/svo/light_types.h"
#include "shaders/shared/svo/build_kernel.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::svo {
namespace {

using Group = SparseLayout::Group;

// Values of a tile's 8 children (nodes or leaves) at tree level `level`: pyramid level depth -
// level, coordinates from the tile's key.
SparseLayout childLayout(const Words& tiles, int depth, std::vector<Group> groups) {
  SparseLayout out;
  out.groups = std::move(groups);
  const size_t count = tiles.size() / shared::kTileWords;
  for (size_t t = 0; t < count; ++t) {
    const uint32_t level = tiles[t * shared::kTileWords + shared::kTileLevel];
    const uint32_t key = tiles[t * shared::kTileWords + shared::kTileKey];
    for (uint32_t local = 0; local < 8; ++local) {
      out.level.push_back(int8_t(depth - int(level)));
      out.coord.emplace_back(shared::mortonDecode((key << 3) | local));
    }
  }
  return out;
}

// Tile records of tree level l at their parent node's voxel: pyramid level depth - l + 1.
SparseLayout tileLayout(const Words& tiles, int depth) {
  SparseLayout out;
  out.groups = {{shared::kTileParent, 1, "_parent"}, {shared::kTileFlags, 1, "_flags"}};
  const size_t count = tiles.size() / shared::kTileWords;
  for (size_t t = 0; t < count; ++t) {
    const int level = int(tiles[t * shared::kTileWords + shared::kTileLevel]);
    out.level.push_back(int8_t(depth - level + 1));
    out.coord.emplace_back(shared::mortonDecode(tiles[t * shared::kTileWords + shared::kTileKey]));
  }
  return out;
}

// A brick's interior texels at their leaves; the boundary texels copy neighbours' interiors.
SparseLayout brickLayout(const Words& leafTiles) {
  SparseLayout out;
  out.groups = {{0, 4, ""}};
  const size_t count = leafTiles.size() / shared::kTileWords;
  for (size_t t = 0; t < count; ++t) {
    const glm::ivec3 base(
        shared::mortonDecode(leafTiles[t * shared::kTileWords + shared::kTileKey]) * 2u);
    for (int texel = 0; texel < shared::kBrickTexels; ++texel) {
      const glm::ivec3 at(texel % 3, texel / 3 % 3, texel / 9);
      const bool interior = at.x < 2 && at.y < 2 && at.z < 2;
      out.level.push_back(interior ? 0 : -1);
      out.coord.push_back(base + at);
    }
  }
  return out;
}

}  // namespace

SparseLayouts sparseLayouts(const BufferSet& run, const GridSpec& grid) {
  SparseLayouts out;
  const Buffer* tiles = run.find(BufferId::svo_build_tiles);
  const Buffer* leafTiles = run.find(BufferId::svo_build_leaf_tiles);
  if (tiles == nullptr || leafTiles == nullptr) return out;
  const int depth = std::countr_zero(unsigned(grid.resolution));
  const std::vector<Group> faces = {{0, 4, "_+x"},  {4, 4, "_-x"},  {8, 4, "_+y"},
                                    {12, 4, "_-y"}, {16, 4, "_+z"}, {20, 4, "_-z"}};
  const std::vector<Group> node = {{shared::kNodeChild, 1, "_child"},
                                   {shared::kNodeNeighbour, 1, "_neighbour_+x"},
                                   {shared::kNodeNeighbour + 1, 1, "_neighbour_-x"},
                                   {shared::kNodeNeighbour + 2, 1, "_neighbour_+y"},
                                   {shared::kNodeNeighbour + 3, 1, "_neighbour_-y"},
                                   {shared::kNodeNeighbour + 4, 1, "_neighbour_+z"},
                                   {shared::kNodeNeighbour + 5, 1, "_neighbour_-z"},
                                   {shared::kNodeFlags, 1, "_flags"}};
  const std::vector<Group> sums = {{shared::kSumOpacity, 1, "_opacity"},
                                   {shared::kSumAlbedo, 3, "_albedo"},
                                   {shared::kSumNormal, 3, "_normal"},
                                   {shared::kSumEmission, 3, "_emission"}};
  out[BufferId::svo_build_nodes] = childLayout(tiles->words, depth, node);
  out[BufferId::svo_build_tiles] = tileLayout(tiles->words, depth);
  out[BufferId::svo_build_leaf_tiles] = tileLayout(leafTiles->words, depth);
  const SparseLayout leaves = childLayout(leafTiles->words, depth, {{0, 4, ""}});
  SparseLayout leafSums = leaves;
  leafSums.groups = sums;
  // The sums' scales are no voxel: metadata of the sums' grids.
  if (const Buffer* s = run.find(BufferId::svo_build_scales))
    leafSums.metadata = {{"voxgi_svo_weight_scale", std::to_string(s->get<float>(0, 0))},
                         {"voxgi_svo_emission_scale", std::to_string(s->get<float>(0, 1))}};
  out[BufferId::svo_build_leaf_sums] = leafSums;
  SparseLayout decoded = leaves;
  decoded.groups = {{kLeafAlbedo, 3, "_albedo"},
                    {kLeafOpacity, 1, "_opacity"},
                    {kLeafNormal, 3, "_normal"},
                    {kLeafEmission, 3, "_emission"}};
  out[BufferId::svo_build_leaves] = decoded;
  for (const BufferId id : {BufferId::svo_propagate_direct, BufferId::svo_propagate_radiance,
                            BufferId::svo_propagate_gathered})
    out[id] = leaves;
  out[BufferId::svo_mip_node_faces] = childLayout(tiles->words, depth, faces);
  out[BufferId::svo_propagate_gathered_bricks] = brickLayout(leafTiles->words);
  out[BufferId::svo_build_scales] = {{-1}, {glm::ivec3(0)}, {}, {}};  // in leaf_sums' metadata
  return out;
}

}  // namespace voxgi::svo
