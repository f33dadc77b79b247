// Octree samples the svo stage tests build trees from.
#pragma once

#include "shaders/shared/svo/build_kernel.h"

namespace voxgi::test {

// A sample filling leaf v exactly (RoI = the cell), so the tree's leaves are the given voxels.
inline shared::SvoSample cellSample(glm::ivec3 v) {
  shared::SvoSample s{};
  s.position = glm::vec3(v) + 0.5f;
  s.edge = 1.0f;
  s.albedo = glm::vec3(0.5f);
  s.density = 1.0f;
  s.normal = glm::vec3(0.0f, 1.0f, 0.0f);
  return s;
}

}  // namespace voxgi::test
