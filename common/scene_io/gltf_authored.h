// What a glTF 2.0 file says about its scene, read from the file's own JSON: materials
// (metallic-roughness, KHR_materials_emissive_strength, KHR_materials_specular), and the meshes,
// KHR_lights_punctual lights and perspective cameras its default scene's nodes place. Debian's
// Assimp 5.2.5 drops the emissive strength (an emitter reads 17x too dim in a Blender export) and
// misreads cameras (a full field of view as a half angle, the position counted twice), so voxgi
// takes none of these from Assimp (docs/scene-format.md, "glTF").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "common/scene.h"
#include "common/scene_motion.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {

// A node's mesh and where the node puts it; `nodes` is the node and its ancestors (the file's node
// indices, the root first).
struct GltfMeshInstance {
  size_t mesh;
  glm::dmat4 toWorld;
  std::vector<size_t> nodes;
};

// A glTF texture: its image (by the file's index) and its sampler's wrap modes.
struct GltfTexture {
  size_t image;
  uint32_t wrapS, wrapT;  // shared::kWrapRepeat, ...
};

// The textures a material names (the file's texture indices), read through TEXCOORD_0.
struct GltfMaterialTextures {
  std::optional<size_t> albedo;    // pbrMetallicRoughness.baseColorTexture
  std::optional<size_t> emission;  // emissiveTexture
};

struct GltfAuthored {
  std::vector<Material> materials;                     // by the file's material index
  std::vector<GltfMaterialTextures> materialTextures;  // the same
  std::vector<GltfTexture> textures;                   // by the file's texture index
  std::vector<GltfMeshInstance> meshes;  // in the order the default scene's nodes instance them
  MeshFileExtras extras;                 // lights and perspective cameras, in the same order
  std::vector<std::vector<size_t>> lightNodes, cameraNodes;  // the nodes of each, as `meshes`
  // Every node's own transform (by the file's node index), unkeyed, and whether the file gives it
  // as a matrix (which glTF forbids animating).
  std::vector<NodeMotion> nodes;
  std::vector<bool> nodeMatrix;
};

// Reads `doc` (the JSON of `path`, checked by checkGltf) with every node placed by `transform`
// (the scene file's transform of the mesh entry). Throws InputError naming the file and field.
GltfAuthored readGltfAuthored(const std::string& path, const nlohmann::json& doc,
                              const glm::dmat4& transform);

// glTF's metallic-roughness model as voxgi's Lambert + Phong material (docs/scene-format.md):
// `dielectricF0` is the Fresnel reflectance at normal incidence of the non-metallic part (0.04
// for glTF's default index of refraction 1.5, scaled by KHR_materials_specular).
Material metallicRoughnessMaterial(const glm::vec3& baseColor, float metallic, float roughness,
                                   const glm::vec3& dielectricF0);

// glTF's luminous units to voxgi's radiometric ones: candela to W/sr, lux to W/m^2, at the
// 683 lm/W of the SI candela's definition — the factor Blender's exporter multiplies by.
constexpr double kLumensPerWatt = 683.0;

}  // namespace voxgi
