// The scene model every technique renders: triangle meshes and point clouds with materials, lights,
// a camera, background radiance and the voxel grid. Loaded by common/scene_io/scene_load.cpp
// (docs/scene-format.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "common/grid.h"
#include "common/scene_motion.h"
#include "common/texture.h"

namespace voxgi {

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};    // Lambertian reflectance, each channel in [0, 1]
  glm::vec3 specular{0.0f};  // specular colour, [0, 1]
  float shininess = 0.0f;    // Phong exponent, >= 0
  glm::vec3 emission{0.0f};  // emitted radiance, linear RGB, >= 0
  // Textures (indices into Scene::textures, or shared::kNoTexture): the value at a point is the
  // constant above times the texture there (docs/textures.md).
  uint32_t albedoTexture = shared::kNoTexture;
  uint32_t emissionTexture = shared::kNoTexture;
  bool textured() const {
    return albedoTexture != shared::kNoTexture || emissionTexture != shared::kNoTexture;
  }
  bool emissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
  // Has a Phong lobe: a specular colour and a shininess above 0 (docs/path-tracer.md).
  bool glossy() const {
    return shininess > 0.0f && (specular.x > 0.0f || specular.y > 0.0f || specular.z > 0.0f);
  }
};

// World-space triangles of one material. Positions are double so that a scene far from the
// origin keeps its precision until it is expressed in voxel-local coordinates.
struct Mesh {
  std::string name;  // where it came from, for messages: "file.obj: mesh 'x'"
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec3> triangles;
  uint32_t material = 0;
  // Texture coordinates per vertex, v = 0 at the image's first row (glTF's convention; OBJ's are
  // flipped on import); empty: (0, 0) everywhere.
  std::vector<glm::vec2> texcoords;
  glm::vec2 texcoord(uint32_t vertex) const {
    return texcoords.empty() ? glm::vec2(0.0f) : texcoords[vertex];
  }
};

// A point cloud (docs/svo.md, "Point clouds"): world-space points with one material. Every point
// has a unit normal and a disc radius (from the file, or estimated from its neighbours when the
// scene asks for it: common/scene_io/point_neighbours.h); colours are optional.
struct PointCloud {
  std::string name;  // the file it came from, for messages
  std::vector<glm::dvec3> positions;
  std::vector<glm::vec3> normals;  // unit, world space
  std::vector<float> radii;        // disc radius, world units, > 0
  std::vector<glm::vec3> colors;   // linear albedo in [0, 1] per point; empty: the material's
  uint32_t material = 0;
  size_t size() const { return positions.size(); }
};

// Light falloff: inverse square (physical default) or [Kahl 2019]'s constant-linear-quadratic.
struct Falloff {
  enum class Kind { inverse_square, polynomial } kind = Kind::inverse_square;
  float constant = 1.0f, linear = 0.0f, quadratic = 0.0f;
  bool operator==(const Falloff&) const = default;
};

struct Light {
  enum class Type { point, spot, directional } type = Type::point;
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, -1.0, 0.0};  // unit; spot axis or direction light travels
  glm::vec3 intensity{1.0f};             // W/sr (point, spot) or irradiance (directional)
  float spotAngleDeg = 45.0f;            // full cone angle of a spot light
  Falloff falloff;
  bool castsShadows = true;
  bool operator==(const Light&) const = default;
};

// A light type by its name in scene files and glTF ("point", "spot", "directional"); nullopt for
// any other.
std::optional<Light::Type> lightType(std::string_view name);

struct Camera {
  glm::dvec3 position{0.0, 0.0, 5.0};
  glm::dvec3 lookAt{0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fovYDeg = 40.0;
  int width = 256, height = 256;
  bool operator==(const Camera&) const = default;
};

struct Scene {
  std::string file;  // the file it was loaded from, for messages
  std::vector<Material> materials;
  TexturePool textures;  // every image the materials use, decoded with its mip levels
  std::vector<Mesh> meshes;
  std::vector<PointCloud> pointClouds;
  std::vector<Light> lights;
  Camera camera;
  glm::vec3 background{0.0f};
  GridSpec grid;  // always set: from the file or fitted around the geometry
  // The file's "settings" as "key=value" (common/settings.h keys, already validated); applied
  // before a --preset and --set.
  std::vector<std::string> settings;
  // Set when voxgi lit a bare file that has no light of its own
  // (common/scene_io/default_lights.cpp), for `voxgi plan` and `render` to say so.
  bool defaultLights = false;
  // What moves, and how (docs/motion.md); empty for a still scene. sceneAt evaluates it.
  SceneMotion motion;

  size_t triangleCount() const;
  // Nothing emits light: no light, no emissive material on a mesh or cloud, a black background.
  bool unlit() const;
  size_t pointCount() const;
  // Bounds of all mesh vertices and points; min > max when there is no geometry.
  std::pair<glm::dvec3, glm::dvec3> bounds() const;
};

// A cube around the bounds with a margin of `margin` (fraction of the largest extent) on each
// side; a unit cube around the origin for an empty scene.
GridSpec fitGrid(const std::pair<glm::dvec3, glm::dvec3>& bounds, int resolution,
                 double margin = 0.05);

}  // namespace voxgi
