#include "validation/reference/spherical_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace voxgi::reference {
namespace {

using glm::dvec3;

// The angle between two vectors, accurate near 0 and pi where acos of the cosine is not.
double angleBetween(const dvec3& u, const dvec3& v) {
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

// v normalised, or nothing when it has no length to normalise.
std::optional<dvec3> unit(const dvec3& v) {
  const double len = glm::length(v);
  if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
  return v / len;
}

// [Van Oosterom & Strackee 1983]'s formula for the solid angle of the triangle of unit directions
// a, b, c: no cancellation for small triangles, unlike the sum of the spherical angles minus pi.
double solidAngleOf(const dvec3& a, const dvec3& b, const dvec3& c) {
  const double triple = std::abs(glm::dot(a, glm::cross(b, c)));
  return 2.0 * std::atan2(triple, 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

}  // namespace

std::optional<SphericalTriangle> SphericalTriangle::make(const dvec3& x, const dvec3& p0,
                                                         const dvec3& p1, const dvec3& p2) {
  const auto a = unit(p0 - x), b = unit(p1 - x), c = unit(p2 - x);
  if (!a || !b || !c) return std::nullopt;
  const auto nab = unit(glm::cross(*a, *b)), nac = unit(glm::cross(*a, *c));
  if (!nab || !nac) return std::nullopt;
  SphericalTriangle t;
  t.a_ = *a;
  t.b_ = *b;
  t.c_ = *c;
  t.alpha_ = angleBetween(*nab, *nac);
  t.solidAngle_ = solidAngleOf(*a, *b, *c);
  if (!(t.solidAngle_ > 0.0) || !(t.alpha_ > 0.0)) return std::nullopt;
  return t;
}

dvec3 SphericalTriangle::sample(glm::dvec2 u) const {
  // [Arvo 1995b]: the first coordinate fixes the area of the sub-triangle (a, b, c'), which places
  // c' on the arc from a to c; the second places the point on the arc from b to c' so that the
  // area up to it grows linearly.
  const double area = u.x * solidAngle_;
  const double s = std::sin(area - alpha_), t = std::cos(area - alpha_);
  const double cosAlpha = std::cos(alpha_), sinAlpha = std::sin(alpha_);
  const double p = t - cosAlpha, q = s + sinAlpha * glm::dot(a_, b_);
  double cosB = ((q * t - p * s) * cosAlpha - q) / ((q * s + p * t) * sinAlpha);
  cosB = std::isfinite(cosB) ? std::clamp(cosB, -1.0, 1.0) : 1.0;
  const dvec3 towardC = glm::normalize(c_ - glm::dot(c_, a_) * a_);
  const dvec3 cPrime = cosB * a_ + std::sqrt(std::max(0.0, 1.0 - cosB * cosB)) * towardC;
  const double z = std::clamp(1.0 - u.y * (1.0 - glm::dot(cPrime, b_)), -1.0, 1.0);
  const auto towardCPrime = unit(cPrime - glm::dot(cPrime, b_) * b_);
  if (!towardCPrime) return b_;
  return glm::normalize(z * b_ + std::sqrt(std::max(0.0, 1.0 - z * z)) * *towardCPrime);
}

std::optional<SphericalRectangle> SphericalRectangle::make(const dvec3& x, const dvec3& s,
                                                           const dvec3& ex, const dvec3& ey) {
  const double width = glm::length(ex), height = glm::length(ey);
  if (!(width > 0.0) || !(height > 0.0)) return std::nullopt;
  SphericalRectangle r;
  r.origin_ = x;
  r.x_ = ex / width;
  r.y_ = ey / height;
  r.z_ = glm::cross(r.x_, r.y_);
  const dvec3 d = s - x;
  r.x0_ = glm::dot(d, r.x_);
  r.y0_ = glm::dot(d, r.y_);
  r.z0_ = glm::dot(d, r.z_);
  if (r.z0_ > 0.0) {  // the frame's z points from the rectangle's plane towards x
    r.z0_ = -r.z0_;
    r.z_ = -r.z_;
  }
  if (!(r.z0_ < 0.0)) return std::nullopt;
  r.x1_ = r.x0_ + width;
  r.y1_ = r.y0_ + height;
  // [Urena 2013]: the planes through x and each edge have the normals n0 = (0, z0, -y0),
  // n1 = (-z0, 0, x1), n2 = (0, -z0, y1) and n3 = (z0, 0, -x0), and the polygon's interior
  // angles are the angles between neighbouring planes. Between n0 and n1, say, the cosine is
  // y0 x1 and the sine |z0| |v10| over the same product of lengths, so each angle is the
  // argument of a complex number with no square roots of the normals, and each pair's sum the
  // argument of their product: two atan2 where the four angles would take four acos. The
  // solid angle is the sum of all four minus 2 pi; it cancels to about 1e-15 absolute, 1e-11 of
  // the smallest solid angle the emitters sample this way.
  const double z = std::abs(r.z0_), z2 = r.z0_ * r.z0_;
  const auto radius = [&](double a, double b) { return std::sqrt(a * a + b * b + z2); };
  const double d00 = radius(r.x0_, r.y0_), d10 = radius(r.x1_, r.y0_), d11 = radius(r.x1_, r.y1_),
               d01 = radius(r.x0_, r.y1_);
  // The argument of (a + i b)(c + i e) in [0, 2 pi): a sum of two angles in [0, pi].
  const auto sumOfAngles = [](double a, double b, double c, double e) {
    const double angle = std::atan2(a * e + b * c, a * c - b * e);
    return angle < 0.0 ? angle + 2.0 * std::numbers::pi : angle;
  };
  const double g01 = sumOfAngles(r.y0_ * r.x1_, z * d10, -r.x1_ * r.y1_, z * d11);
  const double g23 = sumOfAngles(r.x0_ * r.y1_, z * d01, -r.x0_ * r.y0_, z * d00);
  r.b0_ = -r.y0_ / std::sqrt(z2 + r.y0_ * r.y0_);
  r.b1_ = r.y1_ / std::sqrt(z2 + r.y1_ * r.y1_);
  r.k_ = 2.0 * std::numbers::pi - g23;
  r.solidAngle_ = g01 - r.k_;
  if (!(r.solidAngle_ > 0.0)) return std::nullopt;
  return r;
}

dvec3 SphericalRectangle::sample(glm::dvec2 u) const {
  // The first coordinate fixes the solid angle left of the plane through x at xu, the second
  // the height on that slice, each inverted in closed form.
  const double au = u.x * solidAngle_ + k_;
  const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
  const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0, 1.0);
  double xu = -(cu * z0_) / std::sqrt(std::max(1.0 - cu * cu, 1e-300));
  xu = std::isfinite(xu) ? std::clamp(xu, x0_, x1_) : (cu > 0.0 ? x1_ : x0_);
  const double d2 = xu * xu + z0_ * z0_, d = std::sqrt(d2);
  const double h0 = y0_ / std::sqrt(d2 + y0_ * y0_), h1 = y1_ / std::sqrt(d2 + y1_ * y1_);
  const double hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
  const double yv = hv2 < 1.0 - 1e-12 ? std::clamp(hv * d / std::sqrt(1.0 - hv2), y0_, y1_) : y1_;
  return origin_ + xu * x_ + yv * y_ + z0_ * z_;
}

}  // namespace voxgi::reference
