// shade (docs/stages/lpv/shade.md): its irradiance (T4, T15 of docs/lpv.md): a constant volume, a
// single VPL's lobe seen against its normal, linearity and the sign of band 1, trilinear weights at
// a cell centre; its direct light with the RSM as shadow map, for a point light and an area light.
#include <cmath>

#include <gtest/gtest.h>

#include "shaders/shared/lpv/inject_kernel.h"
#include "shaders/shared/lpv/shade_kernel.h"
#include "tests/lpv/light_scenes.h"
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
  params.resolution = g.n;
  params.coefficients = g.coefficients;
  params.inverseCellArea = float(1.0 / (s * s));
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

// Direct light with the RSM depth as shadow map: a floor under a point light, a small square
// blocker between them. Beneath the blocker the floor is dark; elsewhere it gets E cos / pi
// exactly as the light delivers it.
TEST(ShadeLpv, ShadowMapDarkensWhatAnOccluderHides) {
  std::vector<Triangle> tris = quad(1, 0.1, {-1, -1}, {2, 2});
  for (const Triangle& t : quad(1, 0.5, {0.4, 0.4}, {0.6, 0.6})) tris.push_back(t);
  Scene scene = makeScene(tris, unitGrid(32), grey(glm::vec3(0.5f)));
  const glm::dvec3 light(0.5, 0.9, 0.5);
  scene.lights.push_back(pointLight(light, glm::vec3(1.0f)));
  int shadowed = 0, lit = 0;
  for (const auto& [e, p, direct] : shadedFloorPixels(scene)) {
    const glm::dvec3 d = light - p;
    const double r = glm::length(d);
    // The blocker's shadow on the floor: the light's rays through [0.4, 0.6]^2 at y = 0.5 reach
    // y = 0.1 at twice the distance from the axis; stay a few texels clear of its edge.
    const glm::dvec2 offset = glm::dvec2(p.x - 0.5, p.z - 0.5) / 2.0;
    const double inside = std::max(std::abs(offset.x), std::abs(offset.y));
    if (inside < 0.1 - 0.01) {
      EXPECT_EQ(direct, glm::vec3(0.0f)) << "pixel " << e << " is in the shadow";
      ++shadowed;
    } else if (inside > 0.1 + 0.01) {
      const double expected = 1.0 / (r * r) * (d.y / r) / M_PI;
      EXPECT_NEAR(direct.x, expected, 1e-4 * expected) << "pixel " << e;
      ++lit;
    }
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 1000);
}

// An emissive square over a floor, a small blocker between them: as an area light, the floor's
// direct light is Lambert's formula where the blocker does not hide the square's centroid (an
// independent 64 x 64 midpoint quadrature of cos cos / (pi r^2) over the square here) and 0
// beneath the blocker, whose shadow is the centroid's: a hard shadow.
TEST(ShadeLpv, AreaLightDirectLightIsLambertsFormulaOutsideTheShadow) {
  std::vector<Triangle> tris = quad(1, 0.1, {-1, -1}, {2, 2});
  for (const Triangle& t : quad(1, 0.5, {0.45, 0.45}, {0.55, 0.55})) tris.push_back(t);
  Scene scene = makeScene(tris, unitGrid(32), grey(glm::vec3(0.5f)));
  addEmitter(scene, downwardSquare(0.9, 0.4, 0.6), glm::vec3(1.0f));
  int shadowed = 0, lit = 0;
  for (const auto& [e, p, direct] : shadedFloorPixels(scene)) {
    // The blocker [0.45, 0.55]^2 at y = 0.5 seen from the triangles' centroids (1/15 from the
    // square's centre along a diagonal): its shadow on y = 0.1 is the blocker scaled by 2 about
    // each, and both hide |x - 0.5|, |z - 0.5| < 0.067; stay clear of that edge and of the
    // penumbra the two shadows leave between them.
    const double reach = std::max(std::abs(p.x - 0.5), std::abs(p.z - 0.5));
    double f = 0.0;  // the form factor by quadrature
    const int k = 64;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const glm::dvec3 q(0.4 + 0.2 * (i + 0.5) / k, 0.9, 0.4 + 0.2 * (j + 0.5) / k);
        const glm::dvec3 d = q - p;
        const double r2 = glm::dot(d, d);
        f += (d.y / std::sqrt(r2)) * (d.y / std::sqrt(r2)) / (M_PI * r2) * (0.04 / (k * k));
      }
    if (reach < 0.05) {
      EXPECT_EQ(direct, glm::vec3(0.0f)) << "pixel " << e << " is in the shadow";
      ++shadowed;
    } else if (reach > 0.3) {
      // E / pi = L F; the quadrature's own error is below 1e-4 at these distances.
      EXPECT_NEAR(direct.x, f, 2e-4 * f) << "pixel " << e;
      ++lit;
    }
  }
  EXPECT_GT(shadowed, 40);  // measured 64 and 1980
  EXPECT_GT(lit, 1000);
}

}  // namespace
}  // namespace voxgi::test
