// Where the elements of a sparse buffer lie as grids, which the technique that owns the buffer
// knows (Technique::sparseLayouts) and the dumps use (common/io/vdb_io.h).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/stage_list.h"

namespace voxgi {

// Where a sparse buffer's elements lie (BufferShape::sparse: an octree's pools, whose places only
// the tree knows; common/svo/level_layout.h): per element its pyramid level (0 the finest, grid
// voxel size h 2^level; -1 for an element that is not a voxel) and voxel coordinate there, and
// which components make which grid (NAME + suffix, then _L<level> above level 0).
struct SparseLayout {
  struct Group {
    int first, count;  // count 1, 3 or 4 (rgb + alpha)
    std::string suffix;
  };
  std::vector<int8_t> level;
  std::vector<glm::ivec3> coord;
  std::vector<Group> groups;
  std::map<std::string, std::string> metadata;  // added to each of the buffer's grids
};
using SparseLayouts = std::map<BufferId, SparseLayout>;

}  // namespace voxgi
