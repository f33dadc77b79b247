// Uniform sampling of the solid angle that a triangle [Arvo 1995b] or a rectangle [Urena 2013]
// subtends at a point: the path tracer's light sampling (docs/path-tracer.md, "Light sampling").
// Each maps [0, 1)² onto the spherical polygon measure-preservingly and continuously, so a
// stratified 2D sample stays stratified in solid angle. Computed in double: the spherical
// angles lose digits in float long before the solid angle is small enough to leave to area
// sampling.
#pragma once

#include <optional>

#include <glm/glm.hpp>

namespace voxgi::reference {

// The triangle (p0, p1, p2) seen from x.
class SphericalTriangle {
 public:
  // Empty when x lies in the triangle's plane or the triangle is degenerate: no solid angle.
  static std::optional<SphericalTriangle> make(const glm::dvec3& x, const glm::dvec3& p0,
                                               const glm::dvec3& p1, const glm::dvec3& p2);
  double solidAngle() const { return solidAngle_; }
  // The unit direction from x for u in [0, 1)²; uniform in solid angle over the triangle.
  glm::dvec3 sample(glm::dvec2 u) const;

 private:
  glm::dvec3 a_, b_, c_;  // unit directions to the vertices
  double alpha_ = 0.0;    // the spherical angle at a_
  double solidAngle_ = 0.0;
};

// The rectangle with corner s and perpendicular edges ex and ey, seen from x.
class SphericalRectangle {
 public:
  // Empty when x lies in the rectangle's plane or the rectangle is degenerate.
  static std::optional<SphericalRectangle> make(const glm::dvec3& x, const glm::dvec3& s,
                                                const glm::dvec3& ex, const glm::dvec3& ey);
  double solidAngle() const { return solidAngle_; }
  // The point on the rectangle for u in [0, 1)²; uniform in solid angle as seen from x.
  glm::dvec3 sample(glm::dvec2 u) const;

 private:
  glm::dvec3 origin_, x_, y_, z_;  // x, and the rectangle's frame (z_ points away from it)
  double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0, z0_ = 0;  // the rectangle in that frame, z0_ < 0
  double b0_ = 0, b1_ = 0, k_ = 0;
  double solidAngle_ = 0.0;
};

}  // namespace voxgi::reference
