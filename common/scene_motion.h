// Motion in a scene (docs/motion.md): keyframed transforms of its objects, lights and camera (a
// scene file's `animation` fields and a glTF file's animations), and the scene at a time. One time
// model: frame f is at f / fps seconds (frameSeconds), as Blender's glTF exporter writes its keys.
// A moving mesh keeps the positions it was loaded with and is moved rigidly from its loaded
// transform to its transform at the time, never re-imported.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace voxgi {

struct Camera;
struct Light;
struct Scene;

// glTF's three interpolations: hold a key's value, lerp between keys, or the cubic Hermite spline
// whose tangents the keys carry.
enum class Interpolation { step, linear, cubic_spline };

// One animated field: keys at strictly increasing times (seconds). Before the first key it holds
// the first value, after the last the last (glTF's clamping). For cubic_spline `values` holds
// three per key, glTF's order: in-tangent, value, out-tangent. A rotation (glm::dquat) is
// interpolated as glTF says: linear is the shortest-arc slerp, a spline's result is normalised.
template <class Value>
struct KeyframesOf {
  Interpolation interpolation = Interpolation::linear;
  std::vector<double> times;
  std::vector<Value> values;
  Value at(double seconds) const;
};
using Keyframes = KeyframesOf<glm::dvec3>;
// More keys than any animation holds: a file that says otherwise is refused.
constexpr size_t kMaxKeyframes = 1000000;
using RotationKeyframes = KeyframesOf<glm::dquat>;

// A scene file's transform (docs/scene-format.md): world = T(translate) R(rotate_deg, X then Y then
// Z) S(scale) p.
struct TransformFields {
  glm::dvec3 translate{0.0}, rotateDeg{0.0}, scale{1.0};
  glm::dmat4 matrix() const;
};

// One node of a transform hierarchy (a scene file's mesh entry, a glTF node): T R S with each
// part fixed or keyed. `rest` is the transform the node was loaded with; a node with no keys is
// `rest` at every time (a glTF node given by a matrix is never keyed: glTF forbids it).
struct NodeMotion {
  glm::dmat4 rest{1.0};
  glm::dvec3 translate{0.0}, scale{1.0};  // the fixed parts of a keyed node
  glm::dmat3 rotation{1.0};
  std::optional<Keyframes> translateKeys, scaleKeys;
  std::optional<Keyframes> rotateDegKeys;       // a scene file's rotate_deg, as angles
  std::optional<RotationKeyframes> rotateKeys;  // a glTF rotation channel
  bool keyed() const { return translateKeys || scaleKeys || rotateDegKeys || rotateKeys; }
  glm::dmat4 at(double seconds) const;
};

// A scene file's transform fields as a node with no keys.
NodeMotion nodeMotion(const TransformFields& fields);

// A chain of nodes, the root first: world(t) = nodes[0](t) * nodes[1](t) * ...
struct NodePath {
  std::vector<NodeMotion> nodes;
  glm::dmat4 at(double seconds) const;
  glm::dmat4 rest() const;
  bool keyed() const;
};

// Meshes moving together: Scene::meshes[firstMesh, firstMesh + meshCount), loaded at
// path.rest(), moved rigidly to path.at(t).
struct MeshMotion {
  size_t firstMesh = 0, meshCount = 0;
  NodePath path;
};

// A light's keyed fields (a direction is normalised after interpolation), or the node path of a
// glTF light (its position the node's origin, its direction the node's -z).
struct LightMotion {
  size_t light = 0;  // index into Scene::lights
  std::optional<Keyframes> position, direction, intensity;
  std::optional<NodePath> path;
};

// The camera's keyed fields, or the node path of a glTF camera (looking down its -z, +y up).
struct CameraMotion {
  std::optional<Keyframes> position, lookAt, up;
  std::optional<NodePath> path;
};

struct SceneMotion {
  std::vector<MeshMotion> meshes;
  std::vector<LightMotion> lights;
  std::optional<CameraMotion> camera;
  bool empty() const { return meshes.empty() && lights.empty() && !camera; }
};

// A camera placed by a node's transform: at its origin, looking down its -z with its +y up. False
// (the camera untouched) when the transform has no view direction and up (a scale of 0, a shear).
bool placeCameraAtNode(Camera& camera, const glm::dmat4& toWorld);
// A light placed by a node's transform: at its origin, shining down its -z. False (the light
// untouched) when the transform has no -z axis (a scale of 0).
bool placeLightAtNode(Light& light, const glm::dmat4& toWorld);

// The time of frame `frame` at `fps` frames per second.
double frameSeconds(int frame, double fps);

// The scene at `seconds`: moving meshes at their transforms then, lights and camera at their keyed
// values; the grid stays the scene's. Throws InputError naming the scene file when a keyed camera
// or direction degenerates there (the camera on its target, a zero direction).
Scene sceneAt(const Scene& scene, double seconds);

}  // namespace voxgi
