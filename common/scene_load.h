// Loading scenes: a JSON scene description (docs/scene-format.md) or a bare mesh file
// (OBJ/MTL, glTF 2.0, PLY via Assimp) with default material, camera and grid.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "common/scene.h"

namespace voxgi {

// Throws InputError naming the file and field for anything malformed.
Scene loadScene(const std::string& path);

// Checks a grid resolution (power of two in [1, kMaxResolution]); throws InputError(file, field).
int readResolution(const std::string& file, const std::string& field, int64_t n);

// Renders `width` pixels wide (1..16384, else InputError naming `source`), the height keeping the
// camera's aspect ratio.
void setImageWidth(Scene& scene, int width, const std::string& source);

// Appends the triangles of a mesh file to `scene`, transformed by `transform`. Materials come from
// the file unless `materialOverride` names one of scene.materials. Throws InputError; call
// validateGeometry afterwards (it rejects NaN/Inf vertices and bad materials).
void importMeshFile(Scene& scene, const std::string& path, const glm::dmat4& transform,
                    const std::optional<uint32_t>& materialOverride);

// Checks that every vertex and index of `scene` is usable; throws InputError naming the mesh.
void validateGeometry(const Scene& scene);

}  // namespace voxgi
