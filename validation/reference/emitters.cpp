#include "validation/reference/emitters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "validation/reference/sampler.h"
#include "validation/reference/spherical_sampling.h"

namespace voxgi::reference {
namespace {

using glm::dvec3;
using glm::vec3;

// Below this solid angle the emitter's 1/d² varies by a few per cent over it, so area sampling
// is as good and cheaper; above the upper bound x is within a thousandth of the emitter's size
// of its plane, where the spherical angles lose their digits. (The spread below decides first;
// these bound what the spherical maps are asked to do.)
constexpr double kMinSolidAngle = 1e-4, kMaxSolidAngle = 6.2;
// Where area sampling's weight cos θ' / d² varies by less than this factor over the emitter,
// sampling by solid angle lowers the variance too little to pay for its cost (docs/path-tracer.md,
// "Light sampling": on the Cornell box a bound of 2 keeps two thirds of its gain at a third of
// its cost; a square light beside the point, spread 2 to 3, keeps all of it).
constexpr float kMinSpread = 2.0f;

// The rectangle that triangles t and u form when they share a diagonal, both as right triangles
// with the same orientation: its corner and edges.
std::optional<Emitter> asRectangle(const std::array<dvec3, 3>& t, const std::array<dvec3, 3>& u) {
  // The vertex of t that u lacks: the rectangle's corner; u's vertex that t lacks: the opposite.
  int corner = -1, opposite = -1, shared = 0;
  for (int i = 0; i < 3; ++i) {
    const bool inU = t[i] == u[0] || t[i] == u[1] || t[i] == u[2];
    shared += inU;
    if (!inU) corner = i;
    if (u[i] != t[0] && u[i] != t[1] && u[i] != t[2]) opposite = i;
  }
  if (shared != 2 || corner < 0 || opposite < 0) return std::nullopt;
  const dvec3 a = t[corner], b = t[(corner + 1) % 3], c = t[(corner + 2) % 3];
  const dvec3 e1 = b - a, e2 = c - a;
  const double l1 = glm::length(e1), l2 = glm::length(e2);
  const dvec3 nt = glm::cross(t[1] - t[0], t[2] - t[0]), nu = glm::cross(u[1] - u[0], u[2] - u[0]);
  constexpr double kTolerance = 1e-6;
  if (!(l1 > 0.0) || !(l2 > 0.0) || std::abs(glm::dot(e1, e2)) > kTolerance * l1 * l2 ||
      glm::length(u[opposite] - (a + e1 + e2)) > kTolerance * std::max(l1, l2) ||
      glm::dot(nt, nu) < (1.0 - kTolerance) * glm::length(nt) * glm::length(nu))
    return std::nullopt;
  Emitter e;
  e.rectangle = true;
  e.p0 = vec3(a);
  e.e1 = vec3(e1);
  e.e2 = vec3(e2);
  e.normal = vec3(glm::normalize(nt));
  e.area = float(l1 * l2);
  return e;
}

// The emitter as x sees it where it is sampled by solid angle; no shape where by area.
struct SphericalView {
  std::optional<SphericalTriangle> triangle;
  std::optional<SphericalRectangle> rectangle;
  double solidAngle = 0.0;
};

// Whether area sampling's weight, cos θ' / d², varies by more than kMinSpread over the emitter
// seen from x: its largest over its smallest value at the corners, the centroid and (for a
// triangle) the middle of the edge opposite p0; a point behind the plane counts 0. Compared
// squared, as cos² θ' d² / d⁶, which needs no square root.
bool spreadsWide(const Emitter& e, vec3 x) {
  const vec3 points[5] = {e.p0, e.p0 + e.e1, e.p0 + e.e2,
                          e.rectangle ? e.p0 + e.e1 + e.e2 : e.p0 + 0.5f * (e.e1 + e.e2),
                          e.p0 + (e.rectangle ? 0.5f : 1.0f / 3.0f) * (e.e1 + e.e2)};
  float lo = INFINITY, hi = 0.0f;
  for (const vec3& p : points) {
    const vec3 d = x - p;
    const float d2 = glm::dot(d, d), c = std::max(0.0f, glm::dot(e.normal, d));
    const float w2 = c * c / (d2 * d2 * d2);
    lo = std::min(lo, w2);
    hi = std::max(hi, w2);
  }
  return !(hi <= kMinSpread * kMinSpread * lo);
}

SphericalView sphericalView(const Emitter& e, vec3 x, LightSampling how) {
  SphericalView view;
  // Behind its plane the emitter lights nothing, however it is sampled: area sampling is cheaper.
  if (how != LightSampling::solid_angle || glm::dot(e.normal, x - e.p0) <= 0.0f) return view;
  if (!spreadsWide(e, x)) return view;
  const dvec3 xd(x);
  if (e.rectangle)
    view.rectangle = SphericalRectangle::make(xd, dvec3(e.p0), dvec3(e.e1), dvec3(e.e2));
  else
    view.triangle =
        SphericalTriangle::make(xd, dvec3(e.p0), dvec3(e.p0 + e.e1), dvec3(e.p0 + e.e2));
  view.solidAngle = view.rectangle  ? view.rectangle->solidAngle()
                    : view.triangle ? view.triangle->solidAngle()
                                    : 0.0;
  if (view.solidAngle < kMinSolidAngle || view.solidAngle > kMaxSolidAngle) return {};
  return view;
}

}  // namespace

void Emitters::addMesh(uint32_t mesh, const std::vector<vec3>& vertices,
                       const std::vector<glm::uvec3>& triangles, vec3 emission,
                       bool trianglesOnly) {
  if (emitterOf_.size() <= mesh) emitterOf_.resize(mesh + 1);
  emitterOf_[mesh].assign(triangles.size(), -1);
  const auto corners = [&](size_t t) {
    const glm::uvec3& tri = triangles[t];
    return std::array<dvec3, 3>{dvec3(vertices[tri.x]), dvec3(vertices[tri.y]),
                                dvec3(vertices[tri.z])};
  };
  for (size_t t = 0; t < triangles.size(); ++t) {
    const std::array<dvec3, 3> p = corners(t);
    const dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(n);
    if (!(len > 0.0)) continue;
    std::optional<Emitter> e;
    if (t + 1 < triangles.size() && !trianglesOnly) e = asRectangle(p, corners(t + 1));
    if (!e)
      e = Emitter{false,         vec3(p[0]), vec3(p[1] - p[0]), vec3(p[2] - p[0]),
                  vec3(n / len), vec3(0.0f), float(0.5 * len)};
    e->emission = emission;
    e->mesh = mesh;
    e->triangle = uint32_t(t);
    emitterOf_[mesh][t] = int32_t(emitters_.size());
    if (e->rectangle) emitterOf_[mesh][++t] = int32_t(emitters_.size());
    emitters_.push_back(*e);
    weight_ += e->area * luminance(emission);
    cdf_.push_back(weight_);
  }
}

glm::vec2 emitterBarycentric(const Emitter& e, vec3 q) {
  // Least squares on the plane: [e1 e2]^T [e1 e2] b = [e1 e2]^T (q - p0), in double.
  const dvec3 e1(e.e1), e2(e.e2), r = dvec3(q) - dvec3(e.p0);
  const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
  const double det = a * c - b * b;
  if (!(det > 0.0)) return glm::vec2(0.0f);
  const double r1 = glm::dot(e1, r), r2 = glm::dot(e2, r);
  return {float((c * r1 - b * r2) / det), float((a * r2 - b * r1) / det)};
}

float Emitters::pickProbability(const Emitter& e) const {
  return e.area * luminance(e.emission) / weight_;
}

EmitterSample Emitters::sample(vec3 x, glm::vec2 u, LightSampling how) const {
  const float target = u.x * weight_;
  const size_t i = std::min(
      size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()), cdf_.size() - 1);
  const glm::dvec2 v(stretch(target, i == 0 ? 0.0f : cdf_[i - 1], cdf_[i]), u.y);
  const Emitter& e = emitters_[i];
  EmitterSample s;
  s.emitter = &e;
  vec3 point;
  const SphericalView view = sphericalView(e, x, how);
  const float omega = float(view.solidAngle);
  if (view.rectangle) {
    point = vec3(view.rectangle->sample(v));
  } else if (view.triangle) {
    // The point where the sampled direction meets the triangle's plane.
    const dvec3 xd(x), dir = view.triangle->sample(v), n(e.normal);
    point = vec3(xd + glm::dot(n, dvec3(e.p0) - xd) / glm::dot(n, dir) * dir);
  } else if (e.rectangle) {
    point = e.p0 + float(v.x) * e.e1 + float(v.y) * e.e2;
  } else {
    const float su = std::sqrt(float(v.x)), u2 = float(v.y);
    point = e.p0 + su * (1.0f - u2) * e.e1 + su * u2 * e.e2;
  }
  vec3 toLight = point - x;
  const float d2 = glm::dot(toLight, toLight);
  s.distance = std::sqrt(d2);
  if (!(s.distance > 0.0f)) return s;  // pdf 0: no sample
  s.direction = toLight / s.distance;
  s.cosLight = glm::dot(e.normal, -s.direction);
  if (s.cosLight <= 0.0f) return s;
  s.pdf =
      omega > 0.0f ? pickProbability(e) / omega : luminance(e.emission) / weight_ * d2 / s.cosLight;
  return s;
}

float Emitters::pdf(vec3 x, uint32_t mesh, uint32_t triangle, float d2, float cosLight,
                    LightSampling how) const {
  if (mesh >= emitterOf_.size() || emitterOf_[mesh].empty()) return 0.0f;
  const int32_t i = emitterOf_[mesh][triangle];
  if (i < 0 || cosLight <= 0.0f) return 0.0f;
  const Emitter& e = emitters_[size_t(i)];
  const float omega = float(sphericalView(e, x, how).solidAngle);
  return omega > 0.0f ? pickProbability(e) / omega
                      : luminance(e.emission) / weight_ * d2 / cosLight;
}

}  // namespace voxgi::reference
