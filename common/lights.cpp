#include "common/lights.h"

#include <cmath>

namespace voxgi {

std::vector<shared::LightData> voxelLights(const Scene& scene) {
  std::vector<shared::LightData> out;
  for (const Light& l : scene.lights) {
    shared::LightData d{};
    d.position = glm::vec4(glm::vec3(scene.grid.toVoxel(l.position)), 1.0f);
    const double halfAngle = 0.5 * l.spotAngleDeg * 3.14159265358979323846 / 180.0;
    d.direction = glm::vec4(glm::vec3(l.direction), static_cast<float>(std::cos(halfAngle)));
    d.intensity = glm::vec4(l.intensity, 0.0f);
    const bool polynomial = l.falloff.kind == Falloff::Kind::polynomial;
    d.falloff = glm::vec4(l.falloff.constant, l.falloff.linear, l.falloff.quadratic,
                          polynomial ? 1.0f : 0.0f);
    const uint32_t type = l.type == Light::Type::point  ? shared::kLightPoint
                          : l.type == Light::Type::spot ? shared::kLightSpot
                                                        : shared::kLightDirectional;
    d.info = glm::uvec4(type, l.castsShadows ? 1u : 0u, 0u, 0u);
    out.push_back(d);
  }
  return out;
}

}  // namespace voxgi
