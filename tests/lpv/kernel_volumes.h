// The shared propagation kernel's accessor over volumes laid out as the buffers are (a cell's 3C
// words together), for tests that run shared::propagateCell cell by cell as the reference of the
// CPU lanes and the stage (propagate_lanes_test.cpp, propagate_test.cpp).
#pragma once

#include <vector>

#include "shaders/shared/lpv/storage.h"

namespace voxgi::test {

struct KernelVolumes {
  const std::vector<shared::PropagationEntry>& entries;
  const std::vector<float>& previous;
  const std::vector<glm::vec4>* blocking;  // null: no occlusion
  std::vector<float>& next;
  std::vector<float>* accumulated;  // null: not accumulated
  shared::PropagateParams params;
  int n, coefficients;

  size_t cell(glm::ivec3 v) const {
    return size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z));
  }
  int coefficientCount() const { return coefficients; }
  static int colourCount() { return 3; }
  const shared::PropagationEntry& entryAt(int e) const { return entries[size_t(e)]; }
  float intensityAt(glm::ivec3 c, int word) const {
    return previous[cell(c) * size_t(3 * coefficients) + size_t(word)];
  }
  glm::vec4 blockingAt(glm::ivec3 g) const {
    if (glm::any(glm::lessThan(g, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(g, glm::ivec3(n))))
      return glm::vec4(0.0f);
    return (*blocking)[cell(g)];
  }
  void storeIntensity(glm::ivec3 c, int word, float value) const {
    const size_t w = cell(c) * size_t(3 * coefficients) + size_t(word);
    next[w] = value;
    if (accumulated) (*accumulated)[w] = shared::accumulatedValue((*accumulated)[w], value, params);
  }
};

}  // namespace voxgi::test
