#include "tests/lpv/light_scenes.h"

namespace voxgi::test {

const Technique& lpvTechnique() {
  return findTechnique("lpv");
}

std::vector<Triangle> cubeFaces(double lo, double hi) {
  std::vector<Triangle> out;
  for (int axis = 0; axis < 3; ++axis)
    for (double at : {lo, hi})
      for (const Triangle& t : quad(axis, at, {lo, lo}, {hi, hi})) out.push_back(t);
  return out;
}

Material grey(glm::vec3 albedo) {
  Material m;
  m.albedo = albedo;
  return m;
}

Light pointLight(glm::dvec3 at, glm::vec3 intensity) {
  Light l;
  l.type = Light::Type::point;
  l.position = at;
  l.intensity = intensity;
  return l;
}

void addEmitter(Scene& scene, const std::vector<Triangle>& triangles, glm::vec3 radiance) {
  Material emitter;
  emitter.albedo = glm::vec3(0.0f);
  emitter.emission = radiance;
  scene.materials.push_back(emitter);
  Mesh mesh;
  for (const Triangle& t : triangles) {
    const auto first = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), t.begin(), t.end());
    mesh.triangles.emplace_back(first, first + 1, first + 2);
  }
  mesh.material = uint32_t(scene.materials.size() - 1);
  scene.meshes.push_back(mesh);
}

std::vector<Triangle> downwardSquare(double at, double lo, double hi) {
  std::vector<Triangle> out = quad(1, at, {lo, lo}, {hi, hi});
  for (Triangle& t : out) std::swap(t[1], t[2]);
  return out;
}

BufferSet shadeFloor(Scene scene) {
  scene.camera.position = {0.5, 0.45, 0.5};
  scene.camera.lookAt = {0.5, 0.0, 0.5};
  scene.camera.up = {0, 0, -1};
  scene.camera.fovYDeg = 100.0;
  scene.camera.width = scene.camera.height = 64;
  Settings settings;
  settings.lpv.rsmResolution = 128;
  settings.lpv.steps = 1;
  return runCpuUntil(lpvTechnique(), scene, settings, "shade");
}

std::vector<FloorPixel> shadedFloorPixels(const Scene& scene) {
  const BufferSet out = shadeFloor(scene);
  const Buffer &direct = out.at(BufferId::lpv_shade_direct_diffuse),
               &position = out.at(BufferId::common_gbuffer_pixel_position),
               &primitive = out.at(BufferId::common_gbuffer_primitive_id);
  std::vector<FloorPixel> pixels;
  for (size_t e = 0; e < direct.elementCount(); ++e)
    if (const uint32_t id = primitive.get<uint32_t>(e, 0); id == 1 || id == 2)
      pixels.push_back({e, scene.grid.min + glm::dvec3(position.vec3At(e)) * scene.grid.voxelSize(),
                        direct.vec3At(e)});
  return pixels;
}

}  // namespace voxgi::test
