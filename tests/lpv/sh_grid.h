// A free-standing SH grid for the light propagation volume kernel tests: one step of the shared
// propagation kernel (shaders/shared/lpv/propagate_kernel.h) on any grid size, optionally only
// within a box around the centre (cells beyond the light front stay 0 at no cost).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/lpv/propagate.h"

namespace voxgi::test {

struct ShGrid {
  int n = 0, coefficients = 0;
  std::vector<float> words;  // 3 * coefficients per cell, x fastest
  ShGrid(int size, int c) : n(size), coefficients(c), words(size_t(size) * size * size * 3 * c) {}
  size_t first(glm::ivec3 v) const {
    return (size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z))) * 3 *
           size_t(coefficients);
  }
  float& at(glm::ivec3 v, int colour, int i) {
    return words[first(v) + size_t(colour * coefficients + i)];
  }
  float at(glm::ivec3 v, int colour, int i) const {
    return words[first(v) + size_t(colour * coefficients + i)];
  }
  // Sum over the cells of coefficient i of colour 0, in double.
  double total(int i = 0) const;
};

// One propagation step of `from` (occluded by `blocking`, N^3 4-coefficient geometry-volume
// cells, when not null); cells farther than `reach` (infinity norm) from the centre are not
// computed. Adds the step to `accumulated` when given. Only the first `colours` colours are
// propagated (the others stay 0).
ShGrid propagateStep(const ShGrid& from, const lpv::Propagation& setup,
                     const std::vector<glm::vec4>* blocking = nullptr, int reach = 1 << 30,
                     ShGrid* accumulated = nullptr, int colours = 3);

// The propagation setup of `directions` (6, 26) on an n^3 grid with `coefficients` per colour.
lpv::Propagation setupFor(int directions, int coefficients, int n,
                          LpvNormalization normalization = LpvNormalization::energy,
                          bool clampNegative = false);

}  // namespace voxgi::test
