#include "common/cone/cone_sets.h"

#include <cmath>
#include <numbers>

namespace voxgi {
namespace {

constexpr double kPi = std::numbers::pi;

Cone cone(double polar, double azimuth, double aperture, double weight) {
  return {glm::vec3(glm::dvec3(std::sin(polar) * std::cos(azimuth),
                               std::sin(polar) * std::sin(azimuth), std::cos(polar))),
          float(aperture), float(weight)};
}

// A cap and a ring of 6 that split the cosine-weighted hemisphere into 7 parts of equal
// projected solid angle pi / 7: the cap reaches sin^2(theta1) = 1/7; each ring cone sits where
// sin^2(theta) = 4/7 (halfway through the ring's projected area) and has the solid angle of its
// 60-degree sector, 2 pi (1 - cos(alpha)) = (pi / 3) cos(theta1).
std::vector<Cone> equal7() {
  const double cap = std::asin(std::sqrt(1.0 / 7.0));
  const double ringHalf = std::acos(1.0 - std::cos(cap) / 6.0);
  std::vector<Cone> cones{cone(0.0, 0.0, 2.0 * cap, 1.0 / 7.0)};
  for (int k = 0; k < 6; ++k)
    cones.push_back(
        cone(std::asin(std::sqrt(4.0 / 7.0)), k * kPi / 3.0, 2.0 * ringHalf, 1.0 / 7.0));
  return cones;
}

// [Villegas 2017]: 60-degree cones, one along the normal (weight pi/4 of pi) and five at 60 degrees
// from it, 72 degrees apart (3 pi / 20 each).
std::vector<Cone> villegas6() {
  const double aperture = kPi / 3.0;
  std::vector<Cone> cones{cone(0.0, 0.0, aperture, 0.25)};
  for (int k = 0; k < 5; ++k) cones.push_back(cone(kPi / 3.0, k * 2.0 * kPi / 5.0, aperture, 0.15));
  return cones;
}

// [Kahl 2019, §5.4.4]: 0.55 rad cones, front and four intermediate at 45 degrees (kahl5), plus four
// side cones in the tangent plane between them (kahl9). The seed sums the cones unweighted; equal
// weights 1/count keep that shape and a white environment's value.
std::vector<Cone> kahl(bool sides) {
  const double aperture = 0.55;
  const int count = sides ? 9 : 5;
  std::vector<Cone> cones{cone(0.0, 0.0, aperture, 1.0 / count)};
  for (int k = 0; k < 4; ++k)
    cones.push_back(cone(kPi / 4.0, k * kPi / 2.0, aperture, 1.0 / count));
  if (sides)
    for (int k = 0; k < 4; ++k)
      cones.push_back(cone(kPi / 2.0, kPi / 4.0 + k * kPi / 2.0, aperture, 1.0 / count));
  return cones;
}

}  // namespace

std::vector<Cone> diffuseCones(ConeSet set) {
  switch (set) {
    case ConeSet::equal7:
      return equal7();
    case ConeSet::villegas6:
      return villegas6();
    case ConeSet::kahl5:
      return kahl(false);
    case ConeSet::kahl9:
      return kahl(true);
  }
  return {};
}

std::vector<shared::ConeData> coneData(const std::vector<Cone>& cones) {
  std::vector<shared::ConeData> out;
  for (const Cone& c : cones) {
    shared::ConeData d{};
    d.direction = c.direction;
    d.tanHalfAperture = float(std::tan(0.5 * double(c.aperture)));
    d.weight = c.weight;
    out.push_back(d);
  }
  return out;
}

}  // namespace voxgi
