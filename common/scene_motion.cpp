#include "common/scene_motion.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/error.h"
#include "common/scene.h"

namespace voxgi {
namespace {

glm::dvec3 lerpKeys(const glm::dvec3& a, const glm::dvec3& b, double s) {
  return a + (b - a) * s;
}
glm::dquat lerpKeys(const glm::dquat& a, const glm::dquat& b, double s) {
  return glm::slerp(a, b, s);  // glm's slerp takes the shorter arc, as glTF's does
}
glm::dvec3 normalisedKey(const glm::dvec3& v) {
  return v;
}
glm::dquat normalisedKey(const glm::dquat& q) {
  const double length = glm::length(q);
  return length > 0.0 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

glm::dmat3 eulerDegrees(const glm::dvec3& degrees) {
  const glm::dvec3 r = glm::radians(degrees);
  glm::dmat4 m = glm::rotate(glm::dmat4(1.0), r.z, {0, 0, 1});
  m = glm::rotate(m, r.y, {0, 1, 0});
  m = glm::rotate(m, r.x, {1, 0, 0});
  return glm::dmat3(m);
}

glm::dmat4 trs(const glm::dvec3& t, const glm::dmat3& r, const glm::dvec3& s) {
  glm::dmat4 m(r);
  m[0] *= s.x;
  m[1] *= s.y;
  m[2] *= s.z;
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

}  // namespace

template <class Value>
Value KeyframesOf<Value>::at(double seconds) const {
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
      return lerpKeys(value(k), value(k + 1), s);
    case Interpolation::cubic_spline: {
      // glTF 2.0, Appendix C: the Hermite basis, the tangents scaled by the keys' spacing.
      const double s2 = s * s, s3 = s2 * s;
      const Value outTangent = values[3 * k + 2], inTangent = values[3 * (k + 1)];
      return normalisedKey(value(k) * (2.0 * s3 - 3.0 * s2 + 1.0) +
                           outTangent * (span * (s3 - 2.0 * s2 + s)) +
                           value(k + 1) * (-2.0 * s3 + 3.0 * s2) + inTangent * (span * (s3 - s2)));
    }
  }
  return value(k);
}
template struct KeyframesOf<glm::dvec3>;
template struct KeyframesOf<glm::dquat>;

glm::dmat4 TransformFields::matrix() const {
  return trs(translate, eulerDegrees(rotateDeg), scale);
}

NodeMotion nodeMotion(const TransformFields& fields) {
  NodeMotion n;
  n.translate = fields.translate;
  n.rotation = eulerDegrees(fields.rotateDeg);
  n.scale = fields.scale;
  n.rest = trs(n.translate, n.rotation, n.scale);
  return n;
}

glm::dmat4 NodeMotion::at(double seconds) const {
  if (!keyed()) return rest;
  const glm::dmat3 r = rotateKeys      ? glm::mat3_cast(rotateKeys->at(seconds))
                       : rotateDegKeys ? eulerDegrees(rotateDegKeys->at(seconds))
                                       : rotation;
  return trs(translateKeys ? translateKeys->at(seconds) : translate, r,
             scaleKeys ? scaleKeys->at(seconds) : scale);
}

glm::dmat4 NodePath::at(double seconds) const {
  glm::dmat4 m(1.0);
  for (const NodeMotion& n : nodes) m = m * n.at(seconds);
  return m;
}

glm::dmat4 NodePath::rest() const {
  glm::dmat4 m(1.0);
  for (const NodeMotion& n : nodes) m = m * n.rest;
  return m;
}

bool NodePath::keyed() const {
  return std::any_of(nodes.begin(), nodes.end(), [](const NodeMotion& n) { return n.keyed(); });
}

bool placeCameraAtNode(Camera& camera, const glm::dmat4& toWorld) {
  const glm::dvec3 forward = glm::dvec3(toWorld * glm::dvec4(0.0, 0.0, -1.0, 0.0));
  const glm::dvec3 up = glm::dvec3(toWorld * glm::dvec4(0.0, 1.0, 0.0, 0.0));
  const double f = glm::length(forward), u = glm::length(up);
  if (!(f > 0.0 && u > 0.0) || glm::length(glm::cross(forward / f, up / u)) < 1e-6) return false;
  camera.position = glm::dvec3(toWorld[3]);
  // Only the direction to look_at matters; one unit per unit of distance from the origin keeps
  // it distinct from the position in float.
  camera.lookAt = camera.position + forward / f * std::max(1.0, glm::length(camera.position));
  camera.up = up / u;
  return true;
}

bool placeLightAtNode(Light& light, const glm::dmat4& toWorld) {
  const glm::dvec3 axis = glm::dvec3(toWorld * glm::dvec4(0.0, 0.0, -1.0, 0.0));
  if (!(glm::length(axis) > 0.0)) return false;
  light.position = glm::dvec3(toWorld[3]);
  light.direction = glm::normalize(axis);
  return true;
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

std::string atTime(double seconds) {
  return "at " + std::to_string(seconds) + " s ";
}

}  // namespace

Scene sceneAt(const Scene& scene, double seconds) {
  Scene out = scene;
  for (const MeshMotion& m : scene.motion.meshes) {
    // From the loaded pose to the pose at this time, in double.
    const glm::dmat4 move = m.path.at(seconds) * glm::inverse(m.path.rest());
    for (size_t i = m.firstMesh; i < m.firstMesh + m.meshCount; ++i)
      for (glm::dvec3& p : out.meshes[i].positions) p = glm::dvec3(move * glm::dvec4(p, 1.0));
  }
  for (const LightMotion& l : scene.motion.lights) {
    Light& light = out.lights.at(l.light);
    const std::string field = "lights[" + std::to_string(l.light) + "].animation";
    if (l.path && !placeLightAtNode(light, l.path->at(seconds)))
      throw InputError(scene.file, field, atTime(seconds) + "its node has no -z axis (scale 0)");
    if (l.position) light.position = l.position->at(seconds);
    if (l.direction) light.direction = keyedDirection(*l.direction, seconds, scene.file, field);
    if (l.intensity) light.intensity = glm::vec3(glm::max(l.intensity->at(seconds), 0.0));
  }
  if (const std::optional<CameraMotion>& c = scene.motion.camera) {
    Camera& cam = out.camera;
    if (c->path && !placeCameraAtNode(cam, c->path->at(seconds)))
      throw InputError(scene.file, "camera.animation",
                       atTime(seconds) + "its node has no view direction and up (a scale of 0)");
    if (c->position) cam.position = c->position->at(seconds);
    if (c->lookAt) cam.lookAt = c->lookAt->at(seconds);
    if (c->up) cam.up = keyedDirection(*c->up, seconds, scene.file, "camera.animation.up");
    const glm::dvec3 view = cam.lookAt - cam.position;
    if (!(glm::length(view) > 0.0) || !(glm::length(glm::cross(view, cam.up)) > 0.0))
      throw InputError(scene.file, "camera.animation",
                       atTime(seconds) +
                           "the camera looks at its own position or along its up "
                           "vector");
  }
  return out;
}

}  // namespace voxgi
