#include <cmath>
#include <numbers>

#include "common/scene_io/scene_load.h"

namespace voxgi {

void addDefaultLights(Scene& scene) {
  // The camera's frame, so that the key light comes from above, left and behind the viewer
  // whatever way the file's camera looks, and the lit side faces the image.
  const glm::dvec3 forward = glm::normalize(scene.camera.lookAt - scene.camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, scene.camera.up));
  const glm::dvec3 up = glm::cross(right, forward);
  // Directional, so that neither depends on the model's size or units. An irradiance of pi (key)
  // makes a white Lambertian surface facing it reflect a radiance of 1; the fill, a quarter of
  // that from the right and below, casts no shadow, so the key's shadows are not black.
  Light key;
  key.type = Light::Type::directional;
  key.direction = glm::normalize(0.5 * right - 0.8 * up + 0.6 * forward);
  key.intensity = glm::vec3(float(std::numbers::pi));
  Light fill = key;
  fill.direction = glm::normalize(-0.7 * right + 0.3 * up + 0.6 * forward);
  fill.intensity = glm::vec3(float(0.25 * std::numbers::pi));
  fill.castsShadows = false;
  scene.lights = {key, fill};
  scene.defaultLights = true;
}

}  // namespace voxgi
