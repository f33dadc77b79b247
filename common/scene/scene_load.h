// Loading scenes: a JSON scene description (docs/scene-format.md), a bare mesh file (OBJ/MTL,
// glTF 2.0, PLY via Assimp) or a bare point-cloud PLY, with default material, camera and grid.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene.h"

namespace voxgi {

// Throws InputError naming the file and field for anything malformed.
Scene loadScene(const std::string& path);

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

// Appends the triangles of a mesh file to `scene`, transformed by `transform`. Materials come from
// the file unless `materialOverride` names one of scene.materials. Throws InputError; call
// validateGeometry afterwards (it rejects NaN/Inf vertices and bad materials).
void importMeshFile(Scene& scene, const std::string& path, const glm::dmat4& transform,
                    const std::optional<uint32_t>& materialOverride);

// How a point cloud of the scene file is read (docs/scene-format.md, "point_clouds").
struct PointCloudOptions {
  bool estimateNormals = false;         // "normals": "estimate" (else the file must have them)
  std::optional<glm::dvec3> viewpoint;  // estimated normals face it; default: the camera
  enum class Colors { srgb, linear, ignore } colors = Colors::srgb;
};

// Appends the points of a point-cloud PLY (common/scene/point_cloud_ply.h) to `scene`, transformed
// by `transform`, with material `material`. Throws InputError; a cloud without normals is refused
// unless the options estimate them. Radii and normals the file lacks are estimated afterwards, once
// the camera is known, by estimatePointCloudProperties (options per cloud, in order).
void importPointCloud(Scene& scene, const std::string& path, const glm::dmat4& transform,
                      uint32_t material, const PointCloudOptions& options);
void estimatePointCloudProperties(Scene& scene, const std::vector<PointCloudOptions>& options);

// Checks that every vertex and index of `scene` is usable; throws InputError naming the mesh.
void validateGeometry(const Scene& scene);

}  // namespace voxgi
