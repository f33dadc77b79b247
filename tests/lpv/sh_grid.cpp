#include "tests/lpv/sh_grid.h"

#include <algorithm>

#include "shaders/shared/lpv/propagate_kernel.h"

namespace voxgi::test {
namespace {

// The coefficient count as a constant, so the kernel's loops unroll as in cpu/lpv/propagate.cpp.
template <int Coefficients>
struct StepVolumes {
  int colours;
  const lpv::Propagation& setup;
  const ShGrid& from;
  ShGrid* to;
  ShGrid* accumulated;
  const std::vector<glm::vec4>* blocking;

  shared::PropagationEntry entryAt(int e) const { return setup.entries[size_t(e)]; }
  static int coefficientCount() { return Coefficients; }
  int colourCount() const { return colours; }
  float intensityAt(glm::ivec3 cell, int word) const {
    return from.words[from.first(cell) + size_t(word)];
  }
  glm::vec4 blockingAt(glm::ivec3 g) const {
    const int n = from.n;
    if (glm::any(glm::lessThan(g, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(g, glm::ivec3(n))))
      return glm::vec4(0.0f);
    return (*blocking)[size_t(g.x) + size_t(n) * (size_t(g.y) + size_t(n) * size_t(g.z))];
  }
  void storeIntensity(glm::ivec3 cell, int word, float value) const {
    to->words[to->first(cell) + size_t(word)] = value;
    if (accumulated != nullptr) {
      float& a = accumulated->words[accumulated->first(cell) + size_t(word)];
      a = a + value;
    }
  }
};

}  // namespace

double ShGrid::total(int i) const {
  double sum = 0.0;
  for (size_t e = 0; e < words.size(); e += size_t(3 * coefficients)) sum += words[e + size_t(i)];
  return sum;
}

ShGrid propagateStep(const ShGrid& from, const lpv::Propagation& setup,
                     const std::vector<glm::vec4>* blocking, int reach, ShGrid* accumulated,
                     int colours) {
  ShGrid to(from.n, from.coefficients);
  shared::PropagateParams params = setup.params;
  params.occlude = blocking != nullptr ? 1 : 0;
  const int n = from.n, c = n / 2;
  const int lo = std::max(0, c - reach), hi = std::min(n - 1, c + reach);
  const auto run = [&](const auto& volumes) {
    for (int z = lo; z <= hi; ++z)
      for (int y = lo; y <= hi; ++y)
        for (int x = lo; x <= hi; ++x) shared::propagateCell(volumes, glm::ivec3(x, y, z), params);
  };
  if (from.coefficients == 4)
    run(StepVolumes<4>{colours, setup, from, &to, accumulated, blocking});
  else
    run(StepVolumes<9>{colours, setup, from, &to, accumulated, blocking});
  return to;
}

lpv::Propagation setupFor(int directions, int coefficients, int n, LpvNormalization normalization,
                          bool clampNegative) {
  LpvSettings s;
  s.directions = directions == 6 ? LpvDirections::six : LpvDirections::twenty_six;
  s.bands = coefficients == 4 ? 2 : 3;
  s.normalization = normalization;
  s.clampNegative = clampNegative ? LpvToggle::on : LpvToggle::off;
  return lpv::preparePropagation(s, n);
}

}  // namespace voxgi::test
