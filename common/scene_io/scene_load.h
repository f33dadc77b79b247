// Loading scenes: a JSON scene description (docs/scene-format.md), a bare mesh file (OBJ/MTL,
// glTF 2.0, PLY via Assimp) or a bare point-cloud PLY, with default material, camera and grid.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene.h"
#include "common/scene_motion.h"

namespace voxgi {

// Bounds of the scene format (docs/scene-format.md) that files other than the scene JSON meet too:
// positions after their transform, and a light's intensity (W/sr or W/m^2).
constexpr double kMaxCoordinate = 1e15;
constexpr double kMaxLightIntensity = 1e12;
// Texture coordinates: far beyond any authored tiling, small enough to interpolate in float.
constexpr float kMaxTexcoord = 1e6f;

struct SceneLoadOptions {
  // A camera of the scene's mesh files by name (its glTF node's, or the camera's own); empty: the
  // scene file's "camera", else the first camera of its mesh files, else the default.
  std::string camera;
};

// Throws InputError naming the file and field for anything malformed.
Scene loadScene(const std::string& path, const SceneLoadOptions& options = {});
// A scene file's JSON given as text (a scene built in a script): `path` names it in errors, and
// the files it refers to are relative to its folder, as if the text were read from `path`.
Scene loadSceneText(const std::string& text, const std::string& path,
                    const SceneLoadOptions& options = {});

// Checks a grid resolution (power of two in [1, kMaxResolution]); throws InputError(file, field).
int readResolution(const std::string& file, const std::string& field, int64_t n);

// The smallest and largest voxel edge voxgi accepts, in scene units: OpenVDB's transforms (the
// dumps) need a scale well above 1e-7, and float world coordinates (the path tracer) must hold a
// few voxels past the grid.
constexpr double kMinVoxelSize = 1e-6;
constexpr double kMaxVoxelSize = 1e15;

// Checks the scene's grid (voxel size in [kMinVoxelSize, kMaxVoxelSize], the corner within
// 1e15 of the origin); throws InputError naming `source` and grid.size or grid.min. loadScene calls
// it; a command that changes the resolution calls it again.
void checkGrid(const Scene& scene, const std::string& source);

// Renders `width` pixels wide (1..16384, else InputError naming `source`), the height keeping the
// camera's aspect ratio.
void setImageWidth(Scene& scene, int width, const std::string& source);

// A camera of a mesh file, named by its node (or the camera's own name when the node has none).
struct FileCamera {
  std::string name;
  Camera camera;
  NodePath path;  // the nodes that place it (glTF), the import transform's first
};

// What a mesh file carries besides triangles and materials: a glTF file's KHR_lights_punctual
// lights and perspective cameras, in world space (none from OBJ and PLY).
struct MeshFileExtras {
  std::vector<Light> lights;
  std::vector<FileCamera> cameras;
  // A glTF file's node paths, keyed by its animations or not, each starting with a node whose rest
  // is the import transform: of every mesh (Scene::meshes indices) and of each light in `lights`.
  std::vector<MeshMotion> meshPaths;
  std::vector<NodePath> lightPaths;
};

// Appends the triangles of a mesh file to `scene`, transformed by `transform`. Materials come from
// the file unless `materialOverride` names one of scene.materials. Returns the file's lights and
// cameras, transformed the same way. Throws InputError; call validateGeometry afterwards (it
// rejects NaN/Inf vertices and bad materials).
MeshFileExtras importMeshFile(Scene& scene, const std::string& path, const glm::dmat4& transform,
                              const std::optional<uint32_t>& materialOverride);

// How a point cloud of the scene file is read (docs/scene-format.md, "point_clouds").
struct PointCloudOptions {
  bool estimateNormals = false;         // "normals": "estimate" (else the file must have them)
  std::optional<glm::dvec3> viewpoint;  // estimated normals face it; default: the camera
  enum class Colors { srgb, linear, ignore } colors = Colors::srgb;
};

// Appends the points of a point-cloud PLY (common/scene_io/point_cloud_ply.h) to `scene`,
// transformed by `transform`, with material `material`. Throws InputError; a cloud without normals
// is refused unless the options estimate them. Radii and normals the file lacks are estimated
// afterwards, once the camera is known, by estimatePointCloudProperties (options per cloud, in
// order).
void importPointCloud(Scene& scene, const std::string& path, const glm::dmat4& transform,
                      uint32_t material, const PointCloudOptions& options);
void estimatePointCloudProperties(Scene& scene, const std::vector<PointCloudOptions>& options);

// The material "default" (albedo 0.8) of `scene`, added on first use: for meshes and clouds whose
// file gives them none.
uint32_t defaultMaterial(Scene& scene);

// Lights a scene that has none of its own (a bare mesh or cloud, Scene::unlit) with a key and a
// fill directional light placed from its camera, and says so in Scene::defaultLights
// (docs/scene-format.md, "Default lights").
void addDefaultLights(Scene& scene);

// Checks that every vertex and index of `scene` is usable; throws InputError naming the mesh.
void validateGeometry(const Scene& scene);

}  // namespace voxgi
