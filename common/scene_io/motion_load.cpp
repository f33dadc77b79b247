#include "common/scene_io/motion_load.h"

#include <functional>

namespace voxgi {
namespace {

// A keyframed field: {"times": [...], "values": [[x, y, z], ...], "interpolation": ...}; each value
// read by `value` (positions within the scene's bounds, colours in range, ...), a spline's
// tangents only finite.
Keyframes readKeyframes(const Field& f, const std::function<glm::dvec3(const Field&)>& value) {
  f.allowKeys({"times", "values", "interpolation"});
  Keyframes k;
  if (f.has("interpolation")) {
    const Field i = f.at("interpolation");
    const std::string name = i.string();
    if (name == "step")
      k.interpolation = Interpolation::step;
    else if (name == "cubic_spline")
      k.interpolation = Interpolation::cubic_spline;
    else if (name != "linear")
      i.fail("must be \"step\", \"linear\" or \"cubic_spline\", got '" + name + "'");
  }
  const Field times = f.at("times"), values = f.at("values");
  if (!times.value.is_array() || times.value.empty() || times.value.size() > kMaxKeyframes)
    times.fail("must be an array of 1 to " + std::to_string(kMaxKeyframes) + " times (seconds)");
  for (size_t i = 0; i < times.value.size(); ++i) {
    k.times.push_back(times.at(i).number());
    if (i > 0 && !(k.times[i] > k.times[i - 1]))
      times.at(i).fail("must be later than the time before it");
  }
  const bool cubic = k.interpolation == Interpolation::cubic_spline;
  const size_t count = k.times.size() * (cubic ? 3 : 1);
  if (!values.value.is_array() || values.value.size() != count)
    values.fail(
        "must hold " + std::to_string(count) +
        (cubic ? " values (in-tangent, value, out-tangent per time)" : " values, one per time"));
  for (size_t i = 0; i < count; ++i)
    k.values.push_back(cubic && i % 3 != 1 ? values.at(i).vec3() : value(values.at(i)));
  return k;
}

glm::dvec3 readScale(const Field& s) {
  const glm::dvec3 k = s.value.is_array() ? s.vec3() : glm::dvec3(s.number());
  if (k.x == 0.0 || k.y == 0.0 || k.z == 0.0) s.fail("must be non-zero");
  return k;
}
glm::dvec3 readPosition(const Field& f) {
  return f.position();
}
glm::dvec3 readVector(const Field& f) {
  return f.vec3();
}
glm::dvec3 readIntensity(const Field& f) {
  return glm::dvec3(f.color(0.0, kMaxLightIntensity));
}

// The keyframes of `key` in `f`, if it has them.
std::optional<Keyframes> keyed(const Field& f, const char* key,
                               const std::function<glm::dvec3(const Field&)>& value) {
  if (!f.has(key)) return std::nullopt;
  return readKeyframes(f.at(key), value);
}

}  // namespace

TransformFields readTransformFields(const Field& f) {
  f.allowKeys({"translate", "rotate_deg", "scale"});
  TransformFields t;
  if (f.has("translate")) t.translate = f.at("translate").vec3();
  if (f.has("rotate_deg")) t.rotateDeg = f.at("rotate_deg").vec3();
  if (f.has("scale")) t.scale = readScale(f.at("scale"));
  return t;
}

void readMeshMotion(const Field& f, NodeMotion& node) {
  f.allowKeys({"translate", "rotate_deg", "scale"});
  node.translateKeys = keyed(f, "translate", readPosition);
  node.rotateDegKeys = keyed(f, "rotate_deg", readVector);
  node.scaleKeys = keyed(f, "scale", readScale);
}

LightMotion readLightMotion(const Field& f, size_t light) {
  f.allowKeys({"position", "direction", "intensity"});
  LightMotion l;
  l.light = light;
  l.position = keyed(f, "position", readPosition);
  l.direction = keyed(f, "direction", [](const Field& d) { return d.direction(); });
  l.intensity = keyed(f, "intensity", readIntensity);
  return l;
}

CameraMotion readCameraMotion(const Field& f) {
  f.allowKeys({"position", "look_at", "up"});
  CameraMotion c;
  c.position = keyed(f, "position", readPosition);
  c.lookAt = keyed(f, "look_at", readPosition);
  c.up = keyed(f, "up", [](const Field& d) { return d.direction(); });
  return c;
}

}  // namespace voxgi
