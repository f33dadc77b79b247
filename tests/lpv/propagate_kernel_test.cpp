// The propagation kernel on free-standing grids (single-threaded arithmetic, so not in the
// ThreadSanitizer build; propagate_test.cpp runs the stage) against the analytic properties and
// golden values of docs/lpv.md (T8-T13): energy conservation, the thesis-literal quarter per
// step, the clamp's growth, linearity, the 48 cube symmetries, gather against an independent
// scatter, the point-light falloff, one-step leakage and occlusion.
#include <cmath>

#include <gtest/gtest.h>

#include "common/lpv/propagation_faces.h"
#include "shaders/shared/lpv/sh.h"
#include "shaders/shared/lpv/shade_kernel.h"
#include "tests/lpv/sh_grid.h"

namespace voxgi::test {
namespace {

const double kSqrt4Pi = std::sqrt(4.0 * M_PI);

// An isotropic point source of intensity 1 (c0 = sqrt(4 pi)) at the centre of an n^3 grid.
ShGrid isotropicSource(int n, int coefficients) {
  ShGrid g(n, coefficients);
  for (int c = 0; c < 3; ++c) g.at(glm::ivec3(n / 2), c, 0) = float(kSqrt4Pi);
  return g;
}

struct Scheme {
  int directions, coefficients;
};
const Scheme kSchemes[] = {{6, 4}, {6, 9}, {26, 9}, {26, 4}};

// T8: with no occluder and no clamp, sum c0 is unchanged by every step until the front (one cell
// per step) reaches the border.
TEST(Propagate, ConservesEnergyPerStep) {
  const int n = 25;
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    ShGrid g = isotropicSource(n, s.coefficients);
    const double initial = g.total();
    EXPECT_NEAR(initial, 3.544907702, 1e-6);
    for (int step = 1; step < n / 2; ++step) {
      const double before = g.total();
      g = propagateStep(g, setup, nullptr, step, nullptr, 1);
      EXPECT_NEAR(g.total(), before, 1e-6 * initial)
          << s.directions << " directions, " << s.coefficients << " coefficients, step " << step;
    }
  }
}

// T8: Martin's Eq. 3.3 as printed (Omega / 4 pi) keeps exactly a quarter per step.
TEST(Propagate, ThesisNormalizationKeepsAQuarterPerStep) {
  const int n = 17;
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup =
        setupFor(s.directions, s.coefficients, n, LpvNormalization::thesis);
    ShGrid g = isotropicSource(n, s.coefficients);
    for (int step = 1; step <= 4; ++step) {
      const double before = g.total();
      g = propagateStep(g, setup, nullptr, step);
      EXPECT_NEAR(g.total() / before, 0.25, 1e-6) << s.directions << " directions, step " << step;
    }
  }
}

// T9: clamping each face's intensity at 0 adds energy in HOLPV (3.5449 -> 3.6136 after 16 steps
// in an independent simulation (docs/lpv.md, T9)), none in the isotropic LPV-6 case.
TEST(Propagate, ClampAddsBoundedEnergy) {
  const int n = 35;
  for (const Scheme& s : {Scheme{26, 9}, Scheme{6, 4}}) {
    const lpv::Propagation setup =
        setupFor(s.directions, s.coefficients, n, LpvNormalization::energy, /*clampNegative=*/true);
    ShGrid g = isotropicSource(n, s.coefficients);
    const double initial = g.total();
    for (int step = 1; step <= 16; ++step) g = propagateStep(g, setup, nullptr, step, nullptr, 1);
    const double gain = g.total() / initial - 1.0;
    if (s.directions == 26) {
      EXPECT_GE(gain, 0.0);
      EXPECT_LE(gain, 0.025);
      EXPECT_NEAR(g.total(), 3.6136, 2e-3);
    } else {
      EXPECT_NEAR(gain, 0.0, 16 * 1e-6);  // T8's round-off bound per step, over 16 steps
    }
  }
}

// A deterministic pseudo-random grid (values in [-1, 1]).
ShGrid randomGrid(int n, int coefficients, uint32_t seed) {
  ShGrid g(n, coefficients);
  uint32_t x = seed;
  for (float& w : g.words) {
    x = x * 1664525u + 1013904223u;
    w = float(x >> 8) / float(1u << 24) * 2.0f - 1.0f;
  }
  return g;
}

double maxAbs(const ShGrid& g) {
  double m = 0.0;
  for (float w : g.words) m = std::max(m, double(std::abs(w)));
  return m;
}

// T10: propagate(aX + bY) = a propagate(X) + b propagate(Y) with the clamp off.
TEST(Propagate, IsLinear) {
  const int n = 8;
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    const ShGrid x = randomGrid(n, s.coefficients, 1), y = randomGrid(n, s.coefficients, 2);
    ShGrid sum(n, s.coefficients);
    for (size_t w = 0; w < sum.words.size(); ++w)
      sum.words[w] = 0.5f * x.words[w] - 2.0f * y.words[w];
    const ShGrid px = propagateStep(x, setup), py = propagateStep(y, setup),
                 psum = propagateStep(sum, setup);
    const double scale = maxAbs(psum);
    for (size_t w = 0; w < sum.words.size(); ++w)
      ASSERT_NEAR(psum.words[w], 0.5 * px.words[w] - 2.0 * py.words[w], 2e-6 * scale) << w;
  }
}

// Y_i(d) in double, the independent reference of the tests below.
double basis(int i, const glm::dvec3& d) {
  const double k0 = 0.5 / std::sqrt(M_PI), k1 = std::sqrt(3.0) * k0, k2 = std::sqrt(15.0) * k0;
  const double v[9] = {k0,
                       -k1 * d.y,
                       k1 * d.z,
                       -k1 * d.x,
                       k2 * d.x * d.y,
                       -k2 * d.y * d.z,
                       std::sqrt(5.0) * k0 / 2.0 * (3.0 * d.z * d.z - 1.0),
                       -k2 * d.x * d.z,
                       k2 / 2.0 * (d.x * d.x - d.y * d.y)};
  return v[i];
}
double lobeFactor(int i) {  // A_l
  return i == 0 ? M_PI : (i < 4 ? 2.0 * M_PI / 3.0 : M_PI / 4.0);
}

// T10: the gather kernel equals a scatter written independently in double from the face table.
TEST(Propagate, GatherEqualsScatter) {
  const int n = 7;
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    const ShGrid x = randomGrid(n, s.coefficients, 3);
    const ShGrid gathered = propagateStep(x, setup);
    std::vector<double> scattered(x.words.size(), 0.0);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          for (const lpv::PropagationFace& f : lpv::propagationFaces(s.directions)) {
            const glm::ivec3 src(i, j, k), dst = src + f.offset;
            if (glm::any(glm::lessThan(dst, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(dst, glm::ivec3(n))))
              continue;
            for (int c = 0; c < 3; ++c) {
              double intensity = 0.0;
              for (int q = 0; q < s.coefficients; ++q)
                intensity += x.at(src, c, q) * basis(q, f.direction);
              const double flux = f.solidAngle * intensity;
              for (int q = 0; q < s.coefficients; ++q)
                scattered[x.first(dst) + size_t(c * s.coefficients + q)] +=
                    flux / M_PI * lobeFactor(q) * basis(q, f.normal);
            }
          }
    const double scale = maxAbs(gathered);
    for (size_t w = 0; w < scattered.size(); ++w)
      ASSERT_NEAR(gathered.words[w], scattered[w], 2e-6 * scale) << s.directions << " " << w;
  }
}

// The 9x9 matrix D with Y_i(R^-1 d) = sum_j D_ij Y_j(d) (exact for the cube symmetries: each band
// maps onto itself), from 9 generic directions by Gaussian elimination.
std::array<std::array<double, 9>, 9> shRotation(const glm::dmat3& r) {
  std::array<glm::dvec3, 9> d;
  for (int k = 0; k < 9; ++k)
    d[size_t(k)] = glm::normalize(
        glm::dvec3(std::sin(1.3 * k + 0.2), std::cos(2.1 * k + 0.7), std::sin(0.9 * k + 1.9)));
  const glm::dmat3 inverse = glm::transpose(r);
  std::array<std::array<double, 9>, 9> out{};
  for (int i = 0; i < 9; ++i) {
    // Solve A D_i = b with A_kj = Y_j(d_k), b_k = Y_i(R^-1 d_k).
    double a[9][10];
    for (int k = 0; k < 9; ++k) {
      for (int j = 0; j < 9; ++j) a[k][j] = basis(j, d[size_t(k)]);
      a[k][9] = basis(i, inverse * d[size_t(k)]);
    }
    for (int col = 0; col < 9; ++col) {
      int pivot = col;
      for (int k = col + 1; k < 9; ++k)
        if (std::abs(a[k][col]) > std::abs(a[pivot][col])) pivot = k;
      for (int j = 0; j < 10; ++j) std::swap(a[col][j], a[pivot][j]);
      for (int k = 0; k < 9; ++k) {
        if (k == col) continue;
        const double f = a[k][col] / a[col][col];
        for (int j = 0; j < 10; ++j) a[k][j] -= f * a[col][j];
      }
    }
    for (int j = 0; j < 9; ++j) out[size_t(i)][size_t(j)] = a[j][9] / a[j][j];
  }
  return out;
}

// The grid rotated about its centre by the signed permutation `r`, with its SH coefficients.
ShGrid rotated(const ShGrid& g, const glm::imat3x3& r) {
  const auto d = shRotation(glm::dmat3(r));
  ShGrid out(g.n, g.coefficients);
  const glm::ivec3 centre(g.n / 2);
  for (int k = 0; k < g.n; ++k)
    for (int j = 0; j < g.n; ++j)
      for (int i = 0; i < g.n; ++i) {
        const glm::ivec3 v(i, j, k), to = r * (v - centre) + centre;
        for (int c = 0; c < 3; ++c)
          for (int q = 0; q < g.coefficients; ++q) {
            double sum = 0.0;
            for (int p = 0; p < g.coefficients; ++p) sum += g.at(v, c, p) * d[size_t(p)][size_t(q)];
            out.at(to, c, q) = float(sum);
          }
      }
  return out;
}

// T10: propagation commutes with each of the 48 cube symmetries applied to grid and SH together.
TEST(Propagate, CommutesWithTheCubeSymmetries) {
  const int n = 5;  // odd: symmetric about its centre cell
  const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    const ShGrid x = randomGrid(n, s.coefficients, 4);
    const ShGrid px = propagateStep(x, setup);
    const double scale = maxAbs(px);
    int symmetries = 0;
    for (const auto& p : permutations)
      for (int signs = 0; signs < 8; ++signs) {
        glm::imat3x3 r(0);
        for (int a = 0; a < 3; ++a) r[p[a]][a] = (signs >> a) & 1 ? -1 : 1;
        const ShGrid a = rotated(px, r), b = propagateStep(rotated(x, r), setup);
        for (size_t w = 0; w < a.words.size(); ++w)
          ASSERT_NEAR(a.words[w], b.words[w], 1e-5 * scale)
              << s.directions << " directions, symmetry " << symmetries << ", word " << w;
        ++symmetries;
      }
    EXPECT_EQ(symmetries, 48);
  }
}

// Irradiance E (not / pi) at a cell centre on a surface facing the centre of the grid (its normal
// toward the centre), cell size 1.
double irradianceFacingCentre(const ShGrid& accumulated, glm::ivec3 cell) {
  struct Volumes {
    const ShGrid& g;
    float accumulatedAt(glm::ivec3 c, int word) const { return g.words[g.first(c) + size_t(word)]; }
  };
  shared::ShadeParams p{};
  p.resolution = accumulated.n;
  p.coefficients = accumulated.coefficients;
  p.inverseCellArea = 1.0f;  // 1 / s^2 = 1, no shade.offset
  const glm::vec3 toCentre = glm::normalize(glm::vec3(glm::ivec3(accumulated.n / 2) - cell));
  return M_PI *
         double(shared::lpvIrradiance(Volumes{accumulated}, glm::vec3(cell) + 0.5f, toCentre, p).x);
}

// T11: the point-light falloff. HOLPV keeps E r^2 within 15 % of 1 for 4 <= r <= 10 on the axis
// and the diagonals; LPV-6 diffuses: its E r^2 decays monotonically, below HOLPV's far out.
TEST(Propagate, PointLightFalloff) {
  const int n = 41, steps = 40;
  std::vector<double> lpvAxis;
  for (const Scheme& s : {Scheme{26, 9}, Scheme{6, 4}}) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    ShGrid g = isotropicSource(n, s.coefficients);
    ShGrid accumulated = g;
    // Only the cells that reach the measured ones (at most 10 cells from the centre on every
    // axis; each is sampled at its own centre) by the last step, and only those the light front
    // has reached.
    for (int step = 1; step <= steps; ++step)
      g = propagateStep(g, setup, nullptr, std::min(step, 10 + steps - step), &accumulated, 1);
    const glm::ivec3 c(n / 2);
    for (int r = 4; r <= 10; r += 2) {
      const double axis = irradianceFacingCentre(accumulated, c + glm::ivec3(r, 0, 0)) * r * r;
      RecordProperty((s.directions == 26 ? "holpv_r" : "lpv_r") + std::to_string(r),
                     std::to_string(axis));
      if (s.directions == 26) {
        EXPECT_NEAR(axis, 1.0, 0.15) << "HOLPV on the axis at r = " << r;
        for (const glm::ivec3 d : {glm::ivec3(1, 1, 0), glm::ivec3(1, 1, 1)}) {
          const int k = int(std::lround(r / glm::length(glm::dvec3(d))));
          const glm::ivec3 cell = c + k * d;
          const double dist = glm::length(glm::dvec3(cell - c));
          const double e = irradianceFacingCentre(accumulated, cell) * dist * dist;
          EXPECT_NEAR(e, axis, 0.10 * axis) << "HOLPV isotropy at r = " << r;
        }
      } else {
        if (!lpvAxis.empty()) {
          EXPECT_LT(axis, lpvAxis.back()) << "LPV-6 monotone at r = " << r;
        }
        lpvAxis.push_back(axis);
      }
    }
  }
}

// T12: one step of a flux-1 VPL along +z: the flux landing above, level with and below the
// source, and the flux-weighted centroid's advance (golden values of docs/lpv.md, 4 digits).
TEST(Propagate, OneStepLeakage) {
  struct Golden {
    Scheme scheme;
    double above, level, below, centroid;
  };
  for (const Golden& g : {Golden{{6, 4}, 0.4715, 0.6667, -0.1382, 0.610},
                          Golden{{26, 9}, 0.9180, 0.1077, -0.0256, 0.944}}) {
    const int n = 5;
    const int coefficients = g.scheme.coefficients;
    ShGrid x(n, coefficients);
    for (int q = 0; q < coefficients; ++q)
      x.at(glm::ivec3(2), 0, q) = float(lobeFactor(q) / M_PI * basis(q, {0, 0, 1}));
    const ShGrid y = propagateStep(x, setupFor(g.scheme.directions, coefficients, n));
    double flux[3] = {0, 0, 0}, moment = 0.0, total = 0.0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double f = y.at({i, j, k}, 0, 0) * kSqrt4Pi;
          flux[k > 2 ? 0 : (k == 2 ? 1 : 2)] += f;
          moment += f * (k - 2);
          total += f;
        }
    EXPECT_NEAR(total, 1.0, 1e-6);
    EXPECT_NEAR(flux[0], g.above, 6e-5) << g.scheme.directions;
    EXPECT_NEAR(flux[1], g.level, 6e-5) << g.scheme.directions;
    EXPECT_NEAR(flux[2], g.below, 6e-5) << g.scheme.directions;
    EXPECT_NEAR(moment / total, g.centroid, 6e-4) << g.scheme.directions;
  }
}

// T13: a full wall in the geometry volume (blocking >= 1 toward every face entry) passes no light;
// the blend at a face centre is the mean of the 4 corner cells, 2 at an edge, 1 at a corner.
TEST(Propagate, WallInTheGeometryVolumeBlocksEverything) {
  const int n = 9;
  for (const Scheme& s : kSchemes) {
    const lpv::Propagation setup = setupFor(s.directions, s.coefficients, n);
    ShGrid x(n, s.coefficients);
    for (int c = 0; c < 3; ++c) x.at({4, 4, 2}, c, 0) = float(kSqrt4Pi);
    // An isotropic blocker B = 4 in every direction, so even a blend with the empty cells outside
    // the grid blocks all on every GV cell of the plane z = 3 (corners between LPV layers 3 and 4).
    std::vector<glm::vec4> gv(size_t(n) * n * n, glm::vec4(0.0f));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        gv[size_t(i) + size_t(n) * (size_t(j) + size_t(n) * 3)] =
            glm::vec4(float(4.0 * kSqrt4Pi), 0.0f, 0.0f, 0.0f);
    ShGrid g = x;
    for (int step = 0; step < 4; ++step) g = propagateStep(g, setup, &gv);
    for (int k = 4; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          for (int q = 0; q < 3 * s.coefficients; ++q)
            ASSERT_EQ(g.words[g.first({i, j, k}) + size_t(q)], 0.0f) << i << " " << j << " " << k;
  }
}

}  // namespace
}  // namespace voxgi::test
