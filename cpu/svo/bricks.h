// Every tile of a tree level as a brick on the CPU, the twin of gpu/svo/bricks.h (shaders/svo/
// bricks.comp): svo's propagate lays out the gathered light and every frame's source with it, and
// svo's shade the light its cones read.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/svo/octree.h"

namespace voxgi::cpu::svo {

// Bricks of the tiles of `level` (leaf tiles for level == depth): from `interior`, `components`
// words per voxel, 8 voxels a tile in local-id order, to 27 texels a tile with the positive
// boundary copied from the neighbouring tiles' interiors (0 where there is none), found through
// the parent level's neighbour pointers.
// Out: Words, or std::vector<glm::vec4> (values, as the gather's bricks; `components` then
// counts RGBA values).
template <class Out>
Out completeBricks(const Octree& octree, int level,
                   std::span<const typename Out::value_type> interior, int components);
inline Words completeBricks(const Octree& octree, int level, const Words& interior,
                            int components) {
  return completeBricks<Words>(octree, level, std::span<const uint32_t>(interior), components);
}

}  // namespace voxgi::cpu::svo
