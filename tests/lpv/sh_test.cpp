// The SH basis and clamped-cosine lobe of shaders/shared/lpv/sh.h against quadrature and the
// the lobe's closed-form values [Sloan 2008] (T1-T3 of docs/lpv.md).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "shaders/shared/lpv/sh.h"

namespace voxgi {
namespace {

using shared::shBasis;
using shared::shCosineLobe;

glm::vec3 direction(double theta, double phi) {
  return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                   float(std::cos(theta)));
}

// Midpoint quadrature over the sphere of f(direction), in double.
template <class F>
double integrate(const F& f, int rows = 400) {
  const int cols = 2 * rows;
  const double dt = std::numbers::pi / rows, dp = 2.0 * std::numbers::pi / cols;
  double sum = 0.0;
  for (int r = 0; r < rows; ++r) {
    const double theta = (r + 0.5) * dt, weight = std::sin(theta) * dt * dp;
    for (int c = 0; c < cols; ++c) sum += weight * f(direction(theta, (c + 0.5) * dp));
  }
  return sum;
}

TEST(LpvSh, BasisIsOrthonormal) {  // T1
  for (int i = 0; i < 9; ++i)
    for (int j = i; j < 9; ++j)
      EXPECT_NEAR(integrate([&](glm::vec3 d) { return double(shBasis(i, d)) * shBasis(j, d); }),
                  i == j ? 1.0 : 0.0, 2e-5)
          << i << ", " << j;
}

TEST(LpvSh, CosineLobeIsTheProjectionOfTheClampedCosine) {  // T2
  const glm::vec3 normals[] = {glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f)), glm::vec3(0, 0, 1),
                               glm::normalize(glm::vec3(-1.0f, 2.0f, 0.5f))};
  for (const glm::vec3& n : normals)
    for (int i = 0; i < 9; ++i) {
      const double projected = integrate([&](glm::vec3 d) {
        return std::max(0.0, double(glm::dot(n, d))) * double(shBasis(i, d));
      });
      EXPECT_NEAR(projected, shCosineLobe(i, n), 2e-5) << i;
    }
  // Along its own axis the lobe's coefficients are the zonal integrals Z_l of [Martin 2012,
  // Eq. 3.1]: sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8.
  const glm::vec3 z(0, 0, 1);
  EXPECT_NEAR(shCosineLobe(0, z), 0.886226925453, 1e-6);  // Z_0
  EXPECT_NEAR(shCosineLobe(2, z), 1.023326707946, 1e-6);  // Z_1
  EXPECT_NEAR(shCosineLobe(6, z), 0.495415912201, 1e-6);  // Z_2
}

TEST(LpvSh, ReconstructedLobeValues) {  // T3
  const struct {
    double theta, twoBands, threeBands;
  } rows[] = {{0.0, 0.75, 1.0625},
              {std::numbers::pi / 3, 0.5, 0.4609375},
              {std::numbers::pi / 2, 0.25, 0.09375},
              {2 * std::numbers::pi / 3, 0.0, -0.0390625},
              {std::numbers::pi, -0.25, 0.0625}};
  const glm::vec3 z(0, 0, 1);
  for (const auto& row : rows) {
    const glm::vec3 d = direction(row.theta, 0.7);
    double two = 0.0, three = 0.0;
    for (int i = 0; i < 9; ++i) {
      const double term = double(shCosineLobe(i, z)) * shBasis(i, d);
      if (i < 4) two += term;
      three += term;
    }
    EXPECT_NEAR(two, row.twoBands, 1e-6) << row.theta;
    EXPECT_NEAR(three, row.threeBands, 1e-6) << row.theta;
  }
}

}  // namespace
}  // namespace voxgi
