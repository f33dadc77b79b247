#include "common/svo/tree_depth.h"

#include <bit>
#include <string>

#include "common/error.h"

namespace voxgi::svo {

int treeDepth(const Scene& scene) {
  const int n = scene.grid.resolution;
  const int depth = std::countr_zero(unsigned(n));
  if (depth < kMinDepth || depth > kMaxDepth)
    throw InputError(scene.file, "grid.resolution",
                     "the octree's leaves are the grid's voxels: must be in [" +
                         std::to_string(1 << kMinDepth) + ", " + std::to_string(1 << kMaxDepth) +
                         "] for --technique svo, got " + std::to_string(n));
  return depth;
}

}  // namespace voxgi::svo
