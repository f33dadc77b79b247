#include "common/lpv/propagation_faces.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace voxgi::lpv {
namespace {

// The solid angle of the face of the destination cell at `offset` whose outward normal is
// `sign` along `axis`: a unit square in the plane offset[axis] + sign/2 of that axis.
double faceSolidAngle(const glm::ivec3& offset, int axis, int sign, glm::dvec3& centre) {
  centre = glm::dvec3(offset);
  centre[axis] += 0.5 * sign;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return rectangleSolidAngle(centre[u] - 0.5, centre[u] + 0.5, centre[v] - 0.5, centre[v] + 0.5,
                             std::abs(centre[axis]));
}

}  // namespace

double rectangleSolidAngle(double x0, double x1, double y0, double y1, double d) {
  const auto f = [d](double x, double y) {
    return std::atan(x * y / (d * std::sqrt(x * x + y * y + d * d)));
  };
  return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
}

double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double triple = glm::dot(a, glm::cross(b, c));
  const double denominator =
      la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(std::abs(triple), denominator);
}

std::vector<PropagationFace> propagationFaces(int directions) {
  if (directions != 6 && directions != 26)
    throw std::invalid_argument("propagationFaces: directions must be 6 or 26, got " +
                                std::to_string(directions));
  std::vector<PropagationFace> faces;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const glm::ivec3 o(x, y, z);
        const int nonZero = (x != 0) + (y != 0) + (z != 0);
        if (nonZero == 0 || (directions == 6 && nonZero != 1)) continue;
        for (int axis = 0; axis < 3; ++axis) {
          // 26 directions: the faces on the outside of the 3x3x3 block, along each non-zero axis
          // of the offset. 6 directions: the far face, and both side faces of each other axis.
          const bool along = o[axis] != 0;
          if (directions == 26 && !along) continue;
          for (int sign : {-1, 1}) {
            if (along && sign != o[axis]) continue;
            PropagationFace f;
            f.offset = o;
            f.solidAngle = faceSolidAngle(o, axis, sign, f.centre);
            f.direction = glm::normalize(f.centre);
            f.normal = glm::dvec3(0.0);
            f.normal[axis] = sign;
            faces.push_back(f);
          }
        }
      }
  return faces;
}

}  // namespace voxgi::lpv
