// The propagation face tables of common/lpv/propagation_faces.h against the solid angles of
// docs/lpv.md ("Conventions": the front, side and 26-direction solid angles), the thesis's
// two-triangle method and the quadrature moments that make propagation conserve energy (T6 and T7
// of docs/lpv.md).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/lpv/propagation_faces.h"
#include "shaders/shared/lpv/sh.h"

namespace voxgi::lpv {
namespace {

int l1(const glm::ivec3& o) {
  return std::abs(o.x) + std::abs(o.y) + std::abs(o.z);
}

TEST(LpvPropagationFaces, SixDirections) {
  const auto faces = propagationFaces(6);
  ASSERT_EQ(faces.size(), 30u);
  double sum = 0.0;
  for (const PropagationFace& f : faces) {
    sum += f.solidAngle;
    const bool front = glm::dvec3(f.offset) == f.normal;
    // Front 4 asin(1/10), side (2 pi/3 - front)/4; the widespread 0.4234413544 is a typo.
    EXPECT_NEAR(f.solidAngle, front ? 0.4006696846462392 : 0.4234313544367391, 1e-12);
    EXPECT_GT(std::abs(f.solidAngle - 0.4234413544), 1e-6);
    if (!front) {
      EXPECT_EQ(glm::dot(glm::dvec3(f.offset), f.normal), 0.0);
      EXPECT_NEAR(std::abs(glm::dot(f.direction, glm::dvec3(f.offset))), 2.0 / std::sqrt(5.0),
                  1e-15);
    }
  }
  EXPECT_NEAR(sum, 4.0 * std::numbers::pi, 1e-12);
}

TEST(LpvPropagationFaces, TwentySixDirections) {
  const auto faces = propagationFaces(26);
  ASSERT_EQ(faces.size(), 54u);
  const double expected[] = {0.0, 0.4006696846462, 0.2506919694731, 0.1727393849636};
  double sum = 0.0;
  for (const PropagationFace& f : faces) {
    sum += f.solidAngle;
    EXPECT_NEAR(f.solidAngle, expected[l1(f.offset)], 1e-12);
    EXPECT_NE(glm::dot(glm::dvec3(f.offset), f.normal), 0.0);  // faces outwards
  }
  EXPECT_NEAR(sum, 4.0 * std::numbers::pi, 1e-12);
}

// [Martin 2012, App. A]: each face's square pyramid from the source centre as two triangular ones.
TEST(LpvPropagationFaces, TwoTriangleMethodAgrees) {
  for (int directions : {6, 26})
    for (const PropagationFace& f : propagationFaces(directions)) {
      const int axis = f.normal.x != 0 ? 0 : (f.normal.y != 0 ? 1 : 2);
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      glm::dvec3 corner[4];
      for (int k = 0; k < 4; ++k) {
        corner[k] = f.centre;
        corner[k][u] += (k == 1 || k == 2) ? 0.5 : -0.5;
        corner[k][v] += (k >= 2) ? 0.5 : -0.5;
      }
      const double twoTriangles = triangleSolidAngle(corner[0], corner[1], corner[2]) +
                                  triangleSolidAngle(corner[0], corner[2], corner[3]);
      EXPECT_NEAR(twoTriangles, f.solidAngle, 1e-13);
    }
}

// Sum_f Omega_f Y_i(omega_f) = 0 for i > 0 and 4 pi K0 for i = 0; Sum Omega_f omega_f = 0;
// Sum Omega_f omega_f omega_f^T = (4 pi / 3) I.
TEST(LpvPropagationFaces, QuadratureMoments) {
  for (int directions : {6, 26}) {
    const auto faces = propagationFaces(directions);
    for (int i = 0; i < 9; ++i) {
      double moment = 0.0;
      for (const PropagationFace& f : faces)
        moment += f.solidAngle * shared::shBasis(i, glm::vec3(f.direction));
      EXPECT_NEAR(moment, i == 0 ? 2.0 * std::sqrt(std::numbers::pi) : 0.0, 1e-6)
          << directions << " " << i;
    }
    glm::dvec3 first(0.0);
    glm::dmat3 second(0.0);
    for (const PropagationFace& f : faces) {
      first += f.solidAngle * f.direction;
      second += f.solidAngle * glm::outerProduct(f.direction, f.direction);
    }
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(first[a], 0.0, 1e-14);
      for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(second[a][b], a == b ? 4.0 * std::numbers::pi / 3.0 : 0.0, 1e-14) << directions;
    }
  }
}

TEST(LpvPropagationFaces, RefusesOtherCounts) {
  EXPECT_THROW(propagationFaces(8), std::invalid_argument);
}

}  // namespace
}  // namespace voxgi::lpv
