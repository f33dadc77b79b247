// Solid-angle sampling of triangles and rectangles (validation/reference/spherical_sampling.h) and
// the emitters built on it (validation/reference/emitters.h), against values computed another
// way: Girard's theorem for solid angles, Lambert's formula for irradiance, closed forms.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_scenes.h"
#include "validation/reference/emitters.h"
#include "validation/reference/spherical_sampling.h"

namespace voxgi::reference {
namespace {

using glm::dvec3;

// Girard's theorem: a spherical triangle's solid angle is its angle sum minus pi. The interior
// angle at a is between the planes (x, a, b) and (x, a, c). A formula independent of the
// one under test (Van Oosterom and Strackee's), in long double against its cancellation.
double girard(dvec3 x, dvec3 p0, dvec3 p1, dvec3 p2) {
  const auto angle = [&](dvec3 a, dvec3 b, dvec3 c) {
    const dvec3 na = glm::normalize(glm::cross(a - x, b - x)),
                nb = glm::normalize(glm::cross(a - x, c - x));
    return std::acos(std::clamp<long double>(glm::dot(na, nb), -1.0L, 1.0L));
  };
  return double(angle(p0, p1, p2) + angle(p1, p2, p0) + angle(p2, p0, p1) - std::numbers::pi);
}

TEST(SphericalSampling, SolidAnglesAreTheKnownOnes) {
  // An octant: pi/2, either winding.
  const dvec3 o(0.0), ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  EXPECT_NEAR(SphericalTriangle::make(o, ex, ey, ez)->solidAngle(), std::numbers::pi / 2.0, 1e-14);
  EXPECT_NEAR(SphericalTriangle::make(o, ex, ez, ey)->solidAngle(), std::numbers::pi / 2.0, 1e-14);
  // An a x b rectangle seen from height h above a corner: atan(ab / (h sqrt(a² + b² + h²))).
  const double a = 1.0, b = 2.0, h = 0.5;
  const auto corner = [](double w, double l, double z) {
    return std::atan(w * l / (z * std::sqrt(w * w + l * l + z * z)));
  };
  EXPECT_NEAR(SphericalRectangle::make({0, 0, h}, o, a * ex, b * ey)->solidAngle(), corner(a, b, h),
              1e-14);
  EXPECT_NEAR(SphericalRectangle::make({0, 0, -h}, o, a * ex, b * ey)->solidAngle(),
              corner(a, b, h), 1e-14);
  // Above its centre: four corners' worth.
  EXPECT_NEAR(SphericalRectangle::make({a / 2, b / 2, h}, o, a * ex, b * ey)->solidAngle(),
              4.0 * corner(a / 2, b / 2, h), 1e-13);
  // A far and small triangle: area x cosine / distance² from the centroid, to the planar
  // approximation's (size/distance)².
  const dvec3 x(0.3, -0.2, 10.0);
  const double s = 1e-3;
  const auto planar = [&](double area, dvec3 centroid) {
    const dvec3 d = x - centroid;
    return area * d.z / std::pow(glm::dot(d, d), 1.5);
  };
  EXPECT_NEAR(SphericalTriangle::make(x, o, s * ex, s * ey)->solidAngle() /
                  planar(0.5 * s * s, dvec3(s / 3, s / 3, 0)),
              1.0, 1e-7);
  // A rectangle's solid angle cancels to about 1e-15 absolute: at the 1e-4 sr from which the
  // emitters sample by solid angle, 1e-11 of it.
  EXPECT_NEAR(SphericalRectangle::make({0, 0, 1}, o, 1e-2 * ex, 1e-2 * ey)->solidAngle() /
                  corner(1e-2, 1e-2, 1.0),
              1.0, 1e-10);
  // In the polygon's plane there is no solid angle to sample.
  EXPECT_FALSE(SphericalTriangle::make({2, 2, 0}, o, ex, ey).has_value());
  EXPECT_FALSE(SphericalRectangle::make({2, 2, 0}, o, ex, ey).has_value());
}

// A polygon seen from x, a receiver normal that sees all of it, and its split into parts whose
// solid angles Girard's theorem gives.
struct Case {
  const char* name;
  dvec3 x;
  std::vector<dvec3> polygon;  // a triangle, or a rectangle's four corners in order
};

std::vector<Case> cases() {
  return {
      {"triangle near a vertex", {0, 0, 0}, {{0.05, 0, 0.1}, {2, 0, 0.5}, {0, 2, 0.5}}},
      {"triangle, other winding", {0, 0, 0}, {{0.05, 0, 0.1}, {0, 2, 0.5}, {2, 0, 0.5}}},
      {"triangle close above", {0.3, 0.3, 0.05}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
      {"triangle far", {5, -3, 40}, {{0, 0, 0}, {1, 0, 0.3}, {0.2, 1, 0}}},
      {"rectangle oblique", {-0.2, 0.1, 0.3}, {{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}}},
      {"rectangle close above", {0.5, 1, 0.05}, {{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}}},
      {"rectangle tilted", {0.3, 0.2, 2}, {{0, 0, 0}, {1, 1, 0}, {0, 2, 1}, {-1, 1, 1}}},
  };
}

// The point where direction d from x meets the plane of `polygon`.
dvec3 onPlane(dvec3 x, dvec3 d, const std::vector<dvec3>& polygon) {
  const dvec3 n = glm::cross(polygon[1] - polygon[0], polygon[2] - polygon[0]);
  return x + glm::dot(n, polygon[0] - x) / glm::dot(n, d) * d;
}

// The coordinates of p in the triangle (barycentric, weights of p1 and p2) or rectangle (along
// the two edges from polygon[0], each in [0, 1] inside).
glm::dvec2 coordinates(dvec3 p, const std::vector<dvec3>& polygon) {
  const dvec3 e1 = polygon[1] - polygon[0], e2 = polygon.back() - polygon[0], q = p - polygon[0];
  if (polygon.size() == 4)
    return {glm::dot(q, e1) / glm::dot(e1, e1), glm::dot(q, e2) / glm::dot(e2, e2)};
  // Solve q = s e1 + t e2 by least squares (q is in the plane).
  const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2),
               d = glm::dot(q, e1), e = glm::dot(q, e2), det = a * c - b * b;
  return {(c * d - b * e) / det, (a * e - b * d) / det};
}

// Every u of a 512 x 512 midpoint grid maps into the polygon, each of the polygon's parts (the
// triangle's four midpoint triangles, the rectangle's quadrants) receives the share of the grid
// that is its share of the solid angle, and the mean cosine times the solid angle is the
// irradiance that Lambert's formula gives. Area sampling would fail the shares: the cases are
// chosen where area and solid angle differ.
TEST(SphericalSampling, MapsTheUnitSquareUniformlyOntoTheSolidAngle) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<dvec3>& v = c.polygon;
    const bool rectangle = v.size() == 4;
    const dvec3 e1 = v[1] - v[0], e2 = v.back() - v[0];
    std::optional<SphericalTriangle> triangle;
    std::optional<SphericalRectangle> rect;
    if (rectangle)
      rect = SphericalRectangle::make(c.x, v[0], e1, e2);
    else
      triangle = SphericalTriangle::make(c.x, v[0], v[1], v[2]);
    ASSERT_TRUE(rectangle ? rect.has_value() : triangle.has_value());
    const double omega = rectangle ? rect->solidAngle() : triangle->solidAngle();
    const double exactOmega = rectangle
                                  ? girard(c.x, v[0], v[1], v[2]) + girard(c.x, v[0], v[2], v[3])
                                  : girard(c.x, v[0], v[1], v[2]);
    EXPECT_NEAR(omega / exactOmega, 1.0, 1e-12);

    // The parts, in the polygon's coordinates: which part a point is in, and each part's share.
    std::vector<double> share;
    if (rectangle) {
      const dvec3 m01 = v[0] + 0.5 * e1, m03 = v[0] + 0.5 * e2, centre = v[0] + 0.5 * (e1 + e2),
                  m12 = v[1] + 0.5 * e2, m32 = v[3] + 0.5 * e1;
      const std::vector<std::array<dvec3, 4>> quads = {{v[0], m01, centre, m03},
                                                       {m01, v[1], m12, centre},
                                                       {m03, centre, m32, v[3]},
                                                       {centre, m12, v[2], m32}};
      for (const auto& q : quads)
        share.push_back((girard(c.x, q[0], q[1], q[2]) + girard(c.x, q[0], q[2], q[3])) /
                        exactOmega);
    } else {
      const dvec3 m01 = 0.5 * (v[0] + v[1]), m02 = 0.5 * (v[0] + v[2]), m12 = 0.5 * (v[1] + v[2]);
      for (const auto& t : {std::array{v[0], m01, m02}, std::array{m01, v[1], m12},
                            std::array{m02, m12, v[2]}, std::array{m01, m12, m02}})
        share.push_back(girard(c.x, t[0], t[1], t[2]) / exactOmega);
    }
    const auto part = [&](glm::dvec2 st) {
      if (rectangle) return (st.x < 0.5 ? 0 : 1) + (st.y < 0.5 ? 0 : 2);
      return st.x + st.y < 0.5 ? 0 : st.x >= 0.5 ? 1 : st.y >= 0.5 ? 2 : 3;
    };

    // The receiver faces the polygon's plane: it sees all of the polygon.
    dvec3 n = glm::normalize(glm::cross(e1, e2));
    if (glm::dot(v[0] - c.x, n) < 0.0) n = -n;
    constexpr int kGrid = 512;
    std::vector<double> count(4, 0.0);
    double cosineSum = 0.0;
    double worstOutside = 0.0;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const glm::dvec2 u((i + 0.5) / kGrid, (j + 0.5) / kGrid);
        dvec3 d, p;
        if (rectangle) {
          p = rect->sample(u);
          d = glm::normalize(p - c.x);
        } else {
          d = triangle->sample(u);
          p = onPlane(c.x, d, v);
        }
        ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
        const glm::dvec2 st = coordinates(p, v);
        worstOutside = std::max({worstOutside, -st.x, -st.y,
                                 rectangle ? std::max(st.x, st.y) - 1.0 : st.x + st.y - 1.0});
        count[size_t(part(st))] += 1.0;
        cosineSum += glm::dot(n, d);
      }
    EXPECT_LT(worstOutside, 1e-9);
    const double total = double(kGrid) * kGrid;
    for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(count[k] / total, share[k], 2e-3) << "part " << k;
    EXPECT_NEAR(omega * cosineSum / total / (std::numbers::pi * test::polygonFormFactor(v, c.x, n)),
                1.0, 1e-4);
  }
}

// Where the spherical angles are ill-conditioned (the point nearly in the polygon's plane, beside
// an edge's line, a polygon tiny or far), every sample is still a unit direction into the
// polygon, never NaN.
TEST(SphericalSampling, StaysFiniteInHardCases) {
  const dvec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  for (const dvec3& x : {dvec3(0.3, 0.3, 1e-9), dvec3(2.0, 0.0, 1e-7), dvec3(0.5, -1e-9, 1e-9),
                         dvec3(0.2, 0.2, 1e6), dvec3(-1e-7, -1e-7, 1e-7)}) {
    SCOPED_TRACE(x.x);
    const auto t = SphericalTriangle::make(x, p0, p1, p2);
    const auto r = SphericalRectangle::make(x, p0, p1, p2);
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const glm::dvec2 u((i + 0.5) / 16, (j + 0.5) / 16);
        if (t) {
          const dvec3 d = t->sample(u);
          ASSERT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
          ASSERT_NEAR(glm::length(d), 1.0, 1e-9);
          ASSERT_LE(d.z, 1e-12);  // towards the plane
        }
        if (r) {
          const dvec3 p = r->sample(u);
          ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
          ASSERT_GE(p.x, -1e-9);
          ASSERT_LE(p.x, 1.0 + 1e-9);
          ASSERT_GE(p.y, -1e-9);
          ASSERT_LE(p.y, 1.0 + 1e-9);
          ASSERT_NEAR(p.z, 0.0, 1e-9);
        }
      }
  }
}

// A quad given as two triangles is one rectangular emitter: the pdf of a direction to either half
// is one over the whole rectangle's solid angle (seen from a point where area sampling's weight
// varies by 2.6 x over it). A parallelogram that is not a rectangle stays two
// triangles, each picked by its share of the power. By area, the pdf is the power share over the
// area, times distance² over the cosine.
TEST(Emitters, QuadsBecomeRectanglesAndThePdfIsOneOverTheirSolidAngle) {
  const glm::vec3 light(4.0f);
  const dvec3 x(0.2, 0.3, -1.0);  // below the emitters, which face -z
  const std::vector<glm::uvec3> faces = {{0, 1, 3}, {1, 2, 3}};
  const auto toFloat = [](const std::vector<dvec3>& v) {
    return std::vector<glm::vec3>(v.begin(), v.end());
  };
  const std::vector<dvec3> square = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  Emitters rectangle;
  rectangle.addMesh(0, toFloat(square), faces, light);
  const double omega =
      girard(x, square[0], square[1], square[3]) + girard(x, square[1], square[2], square[3]);
  for (uint32_t t = 0; t < 2; ++t)
    EXPECT_NEAR(rectangle.pdf(glm::vec3(x), 0, t, 1.0f, 0.5f, LightSampling::solid_angle) * omega,
                1.0, 1e-5);
  // By area: 1 / area x d² / cos.
  EXPECT_NEAR(rectangle.pdf(glm::vec3(x), 0, 1, 2.0f, 0.5f, LightSampling::area), 4.0, 1e-6);

  const std::vector<dvec3> slanted = {{0, 0, 0}, {0.3, 1, 0}, {1.3, 1, 0}, {1, 0, 0}};
  Emitters parallelogram;
  parallelogram.addMesh(0, toFloat(slanted), faces, light);
  EXPECT_NEAR(parallelogram.pdf(glm::vec3(x), 0, 0, 1.0f, 0.5f, LightSampling::solid_angle) *
                  girard(x, slanted[0], slanted[1], slanted[3]),
              0.5, 1e-5);
  // From far away, where cos θ' / d² varies by less than 2 x over the emitter, and from behind
  // (above), solid angle sampling is not used: the area pdf.
  EXPECT_NEAR(
      rectangle.pdf(glm::vec3(0.5f, 0.5f, -10.0f), 0, 0, 2.0f, 0.5f, LightSampling::solid_angle),
      4.0, 1e-6);
  EXPECT_NEAR(
      parallelogram.pdf(glm::vec3(0.2f, 0.3f, 1.0f), 0, 0, 1.0f, 0.5f, LightSampling::solid_angle),
      2.0, 1e-5);
}

// Every sample lies on the emitter, and its pdf is the one pdf() gives for the triangle it lies
// on: what MIS relies on when a BSDF ray finds the emitter instead. From the first point the
// emitters are sampled by solid angle, from the second (far) by area.
TEST(Emitters, SamplesAgreeWithThePdf) {
  const std::vector<dvec3> v = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {3, 0, 0}, {3, 2, 0}};
  const std::vector<glm::uvec3> faces = {{0, 1, 3}, {1, 2, 3}, {3, 5, 4}};
  Emitters emitters;
  emitters.addMesh(2, std::vector<glm::vec3>(v.begin(), v.end()), faces, glm::vec3(1.0f));
  for (const LightSampling how : {LightSampling::solid_angle, LightSampling::area})
    for (const glm::vec3 x : {glm::vec3(0.5f, 0.5f, -0.2f), glm::vec3(2.0f, 1.0f, -3.0f)})
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
          const EmitterSample s =
              emitters.sample(x, {(float(i) + 0.5f) / 8.0f, (float(j) + 0.5f) / 8.0f}, how);
          ASSERT_GT(s.pdf, 0.0f);
          const glm::vec3 p = x + s.distance * s.direction;
          EXPECT_NEAR(p.z, 0.0f, 1e-5f);
          const uint32_t triangle = p.x <= 1.0f ? (p.x + p.y <= 1.0f ? 0 : 1) : 2;
          EXPECT_NEAR(
              emitters.pdf(x, 2, triangle, s.distance * s.distance, s.cosLight, how) / s.pdf, 1.0f,
              1e-4f)
              << i << " " << j;
        }
}

}  // namespace
}  // namespace voxgi::reference
