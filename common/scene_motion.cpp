#include "common/scene_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/error.h"
#include "common/scene.h"

namespace voxgi {

glm::dvec3 Keyframes::at(double seconds) const {
  const bool cubic = interpolation == Interpolation::cubic_spline;
  // The value of key k (the middle of its three for a spline).
  const auto value = [&](size_t k) { return values[cubic ? 3 * k + 1 : k]; };
  if (seconds <= times.front()) return value(0);
  if (seconds >= times.back()) return value(times.size() - 1);
  const size_t k =
      size_t(std::upper_bound(times.begin(), times.end(), seconds) - times.begin()) - 1;
  const double span = times[k + 1] - times[k], s = (seconds - times[k]) / span;
  switch (interpolation) {
    case Interpolation::step:
      return value(k);
    case Interpolation::linear:
      return value(k) + (value(k + 1) - value(k)) * s;
    case Interpolation::cubic_spline: {
      // glTF 2.0, Appendix C: the Hermite basis, the tangents scaled by the keys' spacing.
      const double s2 = s * s, s3 = s2 * s;
      const glm::dvec3 outTangent = values[3 * k + 2], inTangent = values[3 * (k + 1)];
      return (2.0 * s3 - 3.0 * s2 + 1.0) * value(k) + span * (s3 - 2.0 * s2 + s) * outTangent +
             (-2.0 * s3 + 3.0 * s2) * value(k + 1) + span * (s3 - s2) * inTangent;
    }
  }
  return value(k);
}

glm::dmat4 TransformFields::matrix() const {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
  const glm::dvec3 r = glm::radians(rotateDeg);
  m = glm::rotate(m, r.z, {0, 0, 1});
  m = glm::rotate(m, r.y, {0, 1, 0});
  m = glm::rotate(m, r.x, {1, 0, 0});
  return glm::scale(m, scale);
}

TransformFields MeshMotion::at(double seconds) const {
  TransformFields f = loaded;
  if (translate) f.translate = translate->at(seconds);
  if (rotateDeg) f.rotateDeg = rotateDeg->at(seconds);
  if (scale) f.scale = scale->at(seconds);
  return f;
}

double frameSeconds(int frame, double fps) {
  return double(frame) / fps;
}

namespace {

// A keyed direction, normalised; a zero one (two opposite keys lerped) is an input error.
glm::dvec3 keyedDirection(const Keyframes& k, double seconds, const std::string& file,
                          const std::string& field) {
  const glm::dvec3 d = k.at(seconds);
  const double len = glm::length(d);
  if (!(len > 1e-12))
    throw InputError(file, field,
                     "interpolates to a zero vector at " + std::to_string(seconds) + " s");
  return d / len;
}

}  // namespace

Scene sceneAt(const Scene& scene, double seconds) {
  Scene out = scene;
  for (const MeshMotion& m : scene.motion.meshes) {
    // From the loaded pose to the pose at this time, in double.
    const glm::dmat4 move = m.at(seconds).matrix() * glm::inverse(m.loaded.matrix());
    for (size_t i = m.firstMesh; i < m.firstMesh + m.meshCount; ++i)
      for (glm::dvec3& p : out.meshes[i].positions) p = glm::dvec3(move * glm::dvec4(p, 1.0));
  }
  for (const LightMotion& l : scene.motion.lights) {
    Light& light = out.lights.at(l.light);
    const std::string field = "lights[" + std::to_string(l.light) + "].animation";
    if (l.position) light.position = l.position->at(seconds);
    if (l.direction) light.direction = keyedDirection(*l.direction, seconds, scene.file, field);
    if (l.intensity) light.intensity = glm::vec3(glm::max(l.intensity->at(seconds), 0.0));
  }
  if (const std::optional<CameraMotion>& c = scene.motion.camera) {
    Camera& cam = out.camera;
    if (c->position) cam.position = c->position->at(seconds);
    if (c->lookAt) cam.lookAt = c->lookAt->at(seconds);
    if (c->up) cam.up = keyedDirection(*c->up, seconds, scene.file, "camera.animation.up");
    const glm::dvec3 view = cam.lookAt - cam.position;
    if (!(glm::length(view) > 0.0) || !(glm::length(glm::cross(view, cam.up)) > 0.0))
      throw InputError(scene.file, "camera.animation",
                       "at " + std::to_string(seconds) +
                           " s the camera looks at its own position or along its up vector");
  }
  return out;
}

}  // namespace voxgi
