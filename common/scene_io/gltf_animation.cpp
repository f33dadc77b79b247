#include "common/scene_io/gltf_animation.h"

#include <cmath>

#include "common/error.h"
#include "common/scene_io/gltf_accessor.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {
namespace {

// The keys of one sampler: its times and `components` numbers per value, each value (not the
// spline's tangents) checked by `check`.
template <class Value, size_t components, class Make, class Check>
KeyframesOf<Value> samplerKeys(const std::string& path, const tinygltf::Model& model,
                               const tinygltf::AnimationSampler& sampler, const std::string& field,
                               Make make, Check check) {
  KeyframesOf<Value> k;
  if (sampler.interpolation == "STEP")
    k.interpolation = Interpolation::step;
  else if (sampler.interpolation == "CUBICSPLINE")
    k.interpolation = Interpolation::cubic_spline;
  else if (sampler.interpolation != "LINEAR")
    throw InputError(path, field + ".interpolation",
                     "must be LINEAR, STEP or CUBICSPLINE, got '" + sampler.interpolation + "'");
  const AccessorReader times(path, model, sampler.input, field + ".input");
  if (times.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || times.components != 1)
    times.fail("key times must be float SCALAR");
  if (times.count == 0 || times.count > kMaxKeyframes)
    times.fail("must hold 1 to " + std::to_string(kMaxKeyframes) + " key times");
  for (size_t i = 0; i < times.count; ++i) {
    k.times.push_back(times.number(i, 0));
    if (!std::isfinite(k.times.back())) times.fail("key times must be finite");
    if (i > 0 && !(k.times[i] > k.times[i - 1])) times.fail("key times must increase");
  }
  const AccessorReader values(path, model, sampler.output, field + ".output");
  if (values.components != components)
    values.fail("must hold " + std::to_string(components) + " numbers per key");
  const bool cubic = k.interpolation == Interpolation::cubic_spline;
  const size_t count = times.count * (cubic ? 3 : 1);
  if (values.count != count)
    values.fail("holds " + std::to_string(values.count) + " values for " +
                std::to_string(times.count) + " key times (" + std::to_string(count) +
                " expected)");
  for (size_t i = 0; i < count; ++i) {
    double v[components];
    for (size_t c = 0; c < components; ++c) {
      v[c] = values.number(i, c);
      if (!std::isfinite(v[c]) || std::abs(v[c]) > kMaxCoordinate)
        values.fail("key values must be finite and within 1e15");
    }
    k.values.push_back(make(v));
    if (!cubic || i % 3 == 1) check(values, k.values.back());
  }
  return k;
}

}  // namespace

void readGltfAnimations(const std::string& path, const tinygltf::Model& model,
                        GltfAuthored& authored) {
  for (size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    const std::string where = "animations[" + std::to_string(a) + "]";
    for (size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = animation.channels[c];
      const std::string field = where + ".channels[" + std::to_string(c) + "]";
      if (channel.target_path == "weights") continue;  // morph targets: not read
      if (channel.target_node < 0) continue;           // no node: glTF says the channel is ignored
      if (size_t(channel.target_node) >= authored.nodes.size())
        throw InputError(path, field + ".target.node", "names no node");
      if (channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size())
        throw InputError(path, field + ".sampler", "names no sampler of the animation");
      const size_t node = size_t(channel.target_node);
      if (authored.nodeMatrix[node])
        throw InputError(path, field + ".target.node",
                         "keys node " + std::to_string(node) +
                             ", which has a matrix (glTF animates only translation, rotation and "
                             "scale)");
      NodeMotion& n = authored.nodes[node];
      const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(channel.sampler)];
      const std::string samplerField = where + ".samplers[" + std::to_string(channel.sampler) + "]";
      const auto vec3 = [](const double* v) { return glm::dvec3(v[0], v[1], v[2]); };
      const auto any = [](const AccessorReader&, const glm::dvec3&) {};
      if (channel.target_path == "translation") {
        if (!n.translateKeys)
          n.translateKeys =
              samplerKeys<glm::dvec3, 3>(path, model, sampler, samplerField, vec3, any);
      } else if (channel.target_path == "scale") {
        if (!n.scaleKeys)
          n.scaleKeys = samplerKeys<glm::dvec3, 3>(path, model, sampler, samplerField, vec3, any);
      } else if (channel.target_path == "rotation") {
        // glTF stores x, y, z, w; a key quaternion must be non-zero to be normalised.
        const auto quat = [](const double* v) { return glm::dquat(v[3], v[0], v[1], v[2]); };
        const auto nonZero = [](const AccessorReader& values, const glm::dquat& q) {
          if (!(glm::length(q) > 0.0)) values.fail("a rotation key is the zero quaternion");
        };
        if (!n.rotateKeys) {
          n.rotateKeys =
              samplerKeys<glm::dquat, 4>(path, model, sampler, samplerField, quat, nonZero);
          // The values, not a spline's tangents, are unit quaternions.
          const bool cubic = n.rotateKeys->interpolation == Interpolation::cubic_spline;
          for (size_t i = cubic ? 1 : 0; i < n.rotateKeys->values.size(); i += cubic ? 3 : 1)
            n.rotateKeys->values[i] = glm::normalize(n.rotateKeys->values[i]);
        }
      } else {
        throw InputError(
            path, field + ".target.path",
            "must be translation, rotation, scale or weights, got '" + channel.target_path + "'");
      }
    }
  }
}

}  // namespace voxgi
