// shade's irradiance (T4, T15 of docs/lpv.md): a constant volume, a single VPL's lobe seen
// against its normal, linearity and the sign of band 1, trilinear weights at a cell centre.
#include <cmath>

#include <gtest/gtest.h>

#include "shaders/shared/lpv/inject_kernel.h"
#include "shaders/shared/lpv/shade_kernel.h"
#include "tests/lpv/sh_grid.h"

namespace voxgi::test {
namespace {

struct Volumes {
  const ShGrid& g;
  float accumulatedAt(glm::ivec3 c, int word) const {
    if (glm::any(glm::lessThan(c, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(c, glm::ivec3(g.n))))
      return 0.0f;
    return g.words[g.first(c) + size_t(word)];
  }
};

// E (not / pi) of colour 0 at `p` (voxel-local) with normal n, cell size s.
double irradiance(const ShGrid& g, glm::vec3 p, glm::vec3 n, double s) {
  shared::ShadeParams params{};
  params.shape = glm::ivec4(g.n, g.coefficients, 0, 0);
  params.scale = glm::vec4(float(1.0 / (s * s)), 0.0f, 0.0f, 0.0f);
  return M_PI * double(shared::lpvIrradiance(Volumes{g}, p, n, params).x);
}

TEST(ShadeLpv, ConstantVolumeGivesPiIntensityOverCellArea) {
  for (int coefficients : {4, 9}) {
    ShGrid g(6, coefficients);
    const double i0 = 2.5, s = 0.25;
    for (size_t e = 0; e < g.words.size(); e += size_t(3 * coefficients))
      g.words[e] = float(i0 / 0.282094791773878);  // isotropic intensity i0
    for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, -2, 0.5))})
      for (const glm::vec3 p : {glm::vec3(3.0f), glm::vec3(2.2f, 3.7f, 1.9f)})
        EXPECT_NEAR(irradiance(g, p, n, s), M_PI * i0 / (s * s), 1e-5 * M_PI * i0 / (s * s));
  }
}

// A VPL of flux F about n_p, seen at its own cell's centre by a surface facing it (normal -n_p):
// (F / pi) (lobe . lobe) / s^2, 1.8325957 for 2 bands and 2.0780326 for 3.
TEST(ShadeLpv, SingleVplAgainstItsNormal) {
  const glm::vec3 np = glm::normalize(glm::vec3(0.2f, 0.9f, -0.4f));
  for (const auto& [coefficients, lobeDot] : {std::pair{4, 1.8325957}, std::pair{9, 2.0780326}}) {
    ShGrid g(5, coefficients);
    const double flux = 3.0, s = 2.0;
    for (int i = 0; i < coefficients; ++i)
      g.at({2, 2, 2}, 0, i) = float(flux * shared::shLobeOverPi(i) * shared::shBasis(i, np));
    // Neighbours hold light too: a sample at the cell centre must not see them.
    g.at({3, 2, 2}, 0, 0) = 100.0f;
    g.at({2, 1, 2}, 0, 0) = 100.0f;
    EXPECT_NEAR(irradiance(g, glm::vec3(2.5f), -np, s), flux / M_PI * lobeDot / (s * s), 1e-5);
  }
}

// Band 1 alone: turning the surface around flips the sign; bands 0 and 2 do not change.
TEST(ShadeLpv, FlippingTheNormalFlipsBandOneOnly) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.6f, -0.3f, 0.7f));
  ShGrid odd(3, 9), even(3, 9);
  for (int i = 0; i < 9; ++i) {
    const float v = 0.1f * float(i + 1) - 0.35f;
    (i >= 1 && i < 4 ? odd : even).at({1, 1, 1}, 0, i) = v;
  }
  const glm::vec3 p(1.5f);
  EXPECT_NEAR(irradiance(odd, p, n, 1.0), -irradiance(odd, p, -n, 1.0), 1e-6);
  EXPECT_NEAR(irradiance(even, p, n, 1.0), irradiance(even, p, -n, 1.0), 1e-6);
  EXPECT_NE(irradiance(odd, p, n, 1.0), 0.0);
}

// E is linear in the coefficients, and halfway between two cell centres it is their mean.
TEST(ShadeLpv, TrilinearAndLinear) {
  ShGrid a(4, 4), b(4, 4), sum(4, 4);
  a.at({1, 1, 1}, 0, 0) = 2.0f;
  a.at({1, 1, 1}, 0, 2) = 0.5f;
  b.at({2, 1, 1}, 0, 0) = 1.0f;
  b.at({2, 1, 1}, 0, 3) = -0.25f;
  for (size_t w = 0; w < sum.words.size(); ++w) sum.words[w] = 3.0f * a.words[w] + b.words[w];
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, -1));
  for (const glm::vec3 p : {glm::vec3(2.0f, 1.5f, 1.5f), glm::vec3(1.7f, 1.2f, 1.9f)})
    EXPECT_NEAR(irradiance(sum, p, n, 1.0),
                3.0 * irradiance(a, p, n, 1.0) + irradiance(b, p, n, 1.0), 1e-6);
  const glm::vec3 mid(2.0f, 1.5f, 1.5f);
  EXPECT_NEAR(irradiance(sum, mid, n, 1.0),
              0.5 * (irradiance(sum, glm::vec3(1.5f), n, 1.0) +
                     irradiance(sum, glm::vec3(2.5f, 1.5f, 1.5f), n, 1.0)),
              1e-6);
}

}  // namespace
}  // namespace voxgi::test
