#include "common/lights.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"

namespace voxgi {

std::vector<shared::LightData> voxelLights(const Scene& scene) {
  std::vector<shared::LightData> out;
  for (const Light& l : scene.lights) {
    shared::LightData d{};
    d.position = glm::vec3(scene.grid.toVoxel(l.position));
    const double halfAngle = 0.5 * l.spotAngleDeg * 3.14159265358979323846 / 180.0;
    d.direction = glm::vec3(l.direction);
    d.spotCosine = static_cast<float>(std::cos(halfAngle));
    d.intensity = l.intensity;
    d.falloff = glm::vec3(l.falloff.constant, l.falloff.linear, l.falloff.quadratic);
    d.polynomialFalloff = l.falloff.kind == Falloff::Kind::polynomial ? 1 : 0;
    d.kind = l.type == Light::Type::point  ? shared::kLightPoint
             : l.type == Light::Type::spot ? shared::kLightSpot
                                           : shared::kLightDirectional;
    d.castsShadows = l.castsShadows ? 1u : 0u;
    out.push_back(d);
  }
  return out;
}

size_t emissiveTriangleCount(const Scene& scene) {
  size_t count = 0;
  for (const Mesh& m : scene.meshes)
    if (scene.materials[m.material].emissive()) count += m.triangles.size();
  return count;
}

EmitterLighting emittersFor(const Scene& scene, EmitterLighting setting) {
  if (setting != EmitterLighting::automatic) return setting;
  return emissiveTriangleCount(scene) <= kMaxAreaLights ? EmitterLighting::area_lights
                                                        : EmitterLighting::voxels;
}

size_t areaLightCount(const Scene& scene, EmitterLighting setting) {
  return emittersFor(scene, setting) == EmitterLighting::area_lights ? emissiveTriangleCount(scene)
                                                                     : 0;
}

std::vector<shared::LightData> areaLights(const Scene& scene) {
  std::vector<shared::LightData> out;
  for (const Mesh& mesh : scene.meshes) {
    const Material& m = scene.materials[mesh.material];
    if (!m.emissive()) continue;
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 a = scene.grid.toVoxel(mesh.positions[t.x]),
                       b = scene.grid.toVoxel(mesh.positions[t.y]),
                       c = scene.grid.toVoxel(mesh.positions[t.z]);
      if (glm::length(glm::cross(b - a, c - a)) == 0.0) continue;
      const glm::dvec3 centroid = (a + b + c) / 3.0;
      const double radius = std::max(
          {glm::length(a - centroid), glm::length(b - centroid), glm::length(c - centroid)});
      shared::LightData d{};
      d.position = glm::vec3(a);
      d.boundingRadius = float(radius);
      d.direction = glm::vec3(b);
      d.falloff = glm::vec3(c);
      d.intensity = m.emission;
      d.kind = shared::kLightTriangle;
      d.castsShadows = 1u;
      out.push_back(d);
    }
  }
  if (out.size() > kMaxAreaLights)
    throw InputError(scene.file, "emitters.mode",
                     "area_lights takes at most " + std::to_string(kMaxAreaLights) +
                         " emissive triangles, the scene has " + std::to_string(out.size()) +
                         "; use emitters.mode=voxels");
  return out;
}

std::vector<shared::LightData> sceneLights(const Scene& scene, EmitterLighting setting) {
  std::vector<shared::LightData> lights = voxelLights(scene);
  if (emittersFor(scene, setting) == EmitterLighting::area_lights) {
    const std::vector<shared::LightData> area = areaLights(scene);
    lights.insert(lights.end(), area.begin(), area.end());
  }
  return lights;
}

}  // namespace voxgi
