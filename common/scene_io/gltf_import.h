// glTF 2.0 files (.gltf, .glb): their triangles, materials, lights and cameras as the file's
// default scene places them (docs/scene-format.md, "glTF").
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "common/scene.h"
#include "common/scene_io/gltf_check.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {

// Appends the triangles of `path` (`file`, as checkGltf read it) to `scene`, each
// primitive a Mesh, placed by `transform` times its node's; materials from the file unless
// `materialOverride`. Returns the file's lights and cameras. Throws InputError.
MeshFileExtras importGltf(Scene& scene, const std::string& path, const GltfFile& file,
                          const glm::dmat4& transform,
                          const std::optional<uint32_t>& materialOverride);

}  // namespace voxgi
