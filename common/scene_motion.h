// Motion in a scene (docs/motion.md): keyframed fields of its objects, lights and camera, and the
// scene at a time. One time model: frame f is at f / fps seconds (frameSeconds), as Blender's glTF
// exporter writes its keys. A moving mesh keeps the positions it was loaded with and is moved
// rigidly from its loaded transform to its transform at the time, never re-imported.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace voxgi {

struct Scene;

// glTF's three interpolations: hold a key's value, lerp between keys, or the cubic Hermite spline
// whose tangents the keys carry.
enum class Interpolation { step, linear, cubic_spline };

// One animated field of three numbers: keys at strictly increasing times (seconds). Before the
// first key it holds the first value, after the last the last (glTF's clamping). For
// cubic_spline `values` holds three per key, glTF's order: in-tangent, value, out-tangent.
struct Keyframes {
  Interpolation interpolation = Interpolation::linear;
  std::vector<double> times;
  std::vector<glm::dvec3> values;
  glm::dvec3 at(double seconds) const;
};

// A scene file's transform (docs/scene-format.md): world = T(translate) R(rotate_deg, X then Y then
// Z) S(scale) p.
struct TransformFields {
  glm::dvec3 translate{0.0}, rotateDeg{0.0}, scale{1.0};
  glm::dmat4 matrix() const;
};

// The meshes of one scene-file entry, moving together: each field of their transform keyframed or
// fixed. rotate_deg's keys are interpolated as angles, so a turn of 360 degrees turns.
struct MeshMotion {
  size_t firstMesh = 0, meshCount = 0;  // Scene::meshes[firstMesh, firstMesh + meshCount)
  TransformFields loaded;               // the transform their positions were loaded with
  std::optional<Keyframes> translate, rotateDeg, scale;
  TransformFields at(double seconds) const;
};

// A light's keyed fields (a direction is normalised after interpolation).
struct LightMotion {
  size_t light = 0;  // index into Scene::lights
  std::optional<Keyframes> position, direction, intensity;
};

struct CameraMotion {
  std::optional<Keyframes> position, lookAt, up;
};

struct SceneMotion {
  std::vector<MeshMotion> meshes;
  std::vector<LightMotion> lights;
  std::optional<CameraMotion> camera;
  bool empty() const { return meshes.empty() && lights.empty() && !camera; }
};

// The time of frame `frame` at `fps` frames per second.
double frameSeconds(int frame, double fps);

// The scene at `seconds`: moving meshes at their transforms then, lights and camera at their keyed
// values; the grid stays the scene's. Throws InputError naming the scene file when a keyed camera
// or direction degenerates there (the camera on its target, a zero direction).
Scene sceneAt(const Scene& scene, double seconds);

}  // namespace voxgi
