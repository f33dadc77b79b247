#include "common/scene.h"

#include <algorithm>
#include <limits>

namespace voxgi {

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Mesh& m : meshes) n += m.triangles.size();
  return n;
}

size_t Scene::pointCount() const {
  size_t n = 0;
  for (const PointCloud& c : pointClouds) n += c.size();
  return n;
}

std::optional<Light::Type> lightType(std::string_view name) {
  if (name == "point") return Light::Type::point;
  if (name == "spot") return Light::Type::spot;
  if (name == "directional") return Light::Type::directional;
  return std::nullopt;
}

bool Scene::unlit() const {
  const auto emits = [](const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; };
  if (emits(background)) return false;
  for (const Light& l : lights)
    if (emits(l.intensity)) return false;
  for (const Mesh& m : meshes)
    if (!m.triangles.empty() && materials.at(m.material).emissive()) return false;
  for (const PointCloud& c : pointClouds)
    if (c.size() > 0 && materials.at(c.material).emissive()) return false;
  return true;
}

std::pair<glm::dvec3, glm::dvec3> Scene::bounds() const {
  glm::dvec3 lo(std::numeric_limits<double>::max());
  glm::dvec3 hi(std::numeric_limits<double>::lowest());
  for (const Mesh& m : meshes)
    for (const glm::uvec3& t : m.triangles)
      for (int c = 0; c < 3; ++c) {
        lo = glm::min(lo, m.positions[t[c]]);
        hi = glm::max(hi, m.positions[t[c]]);
      }
  for (const PointCloud& c : pointClouds)  // with each point's disc
    for (size_t i = 0; i < c.size(); ++i) {
      const double r = i < c.radii.size() ? double(c.radii[i]) : 0.0;
      lo = glm::min(lo, c.positions[i] - r);
      hi = glm::max(hi, c.positions[i] + r);
    }
  return {lo, hi};
}

GridSpec fitGrid(const std::pair<glm::dvec3, glm::dvec3>& bounds, int resolution, double margin) {
  GridSpec grid;
  grid.resolution = resolution;
  const auto& [lo, hi] = bounds;
  if (lo.x > hi.x) {
    grid.min = glm::dvec3(-0.5);
    grid.size = 1.0;
    return grid;
  }
  const glm::dvec3 extent = hi - lo;
  double size = std::max({extent.x, extent.y, extent.z});
  // A flat or point-like scene still needs a positive size; scale it with the coordinates.
  const double magnitude = std::max({glm::length(lo), glm::length(hi), 1e-30});
  size = std::max(size, magnitude * 1e-6);
  size *= 1.0 + 2.0 * margin;
  grid.size = size;
  grid.min = 0.5 * (lo + hi) - glm::dvec3(0.5 * size);
  return grid;
}

}  // namespace voxgi
