// Mesh files through Assimp: triangles of every node, in world space, with their materials.
#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "common/error.h"
#include "common/scene_load.h"

namespace voxgi {
namespace {

glm::vec3 color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                glm::vec3 fallback) {
  aiColor4D c;
  if (m.Get(key, type, index, c) == AI_SUCCESS) return {c.r, c.g, c.b};
  return fallback;
}

Material convertMaterial(const aiMaterial& m) {
  Material out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  out.albedo = color(m, AI_MATKEY_COLOR_DIFFUSE, out.albedo);
  out.albedo = color(m, AI_MATKEY_BASE_COLOR, out.albedo);  // glTF metallic-roughness
  out.specular = color(m, AI_MATKEY_COLOR_SPECULAR, out.specular);
  out.emission = color(m, AI_MATKEY_COLOR_EMISSIVE, out.emission);
  float shininess = 0.0f;
  if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS) out.shininess = shininess;
  return out;
}

uint32_t internMaterial(Scene& scene, Material material) {
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == material.name) return static_cast<uint32_t>(i);
  scene.materials.push_back(std::move(material));
  return static_cast<uint32_t>(scene.materials.size() - 1);
}

glm::dmat4 toGlm(const aiMatrix4x4& m) {
  glm::dmat4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[c][r] = m[static_cast<unsigned>(r)][static_cast<unsigned>(c)];
  return out;
}

}  // namespace

void importMeshFile(Scene& scene, const std::string& path, const glm::dmat4& transform,
                    const std::optional<uint32_t>& materialOverride) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "", "no such mesh file");
  Assimp::Importer importer;
  // No degenerate-triangle removal here: the voxelizer handles them (and tests that it does).
  const aiScene* ai = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_JoinIdenticalVertices);
  if (ai == nullptr)
    throw InputError(path, "", std::string("cannot import: ") + importer.GetErrorString());
  std::vector<uint32_t> materialOf(ai->mNumMaterials);
  for (unsigned i = 0; i < ai->mNumMaterials; ++i)
    materialOf[i] = materialOverride ? *materialOverride
                                     : internMaterial(scene, convertMaterial(*ai->mMaterials[i]));

  struct Item {
    const aiNode* node;
    glm::dmat4 toWorld;
  };
  std::vector<Item> stack{{ai->mRootNode, transform * toGlm(ai->mRootNode->mTransformation)}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    for (unsigned c = 0; c < item.node->mNumChildren; ++c)
      stack.push_back({item.node->mChildren[c],
                       item.toWorld * toGlm(item.node->mChildren[c]->mTransformation)});
    for (unsigned mi = 0; mi < item.node->mNumMeshes; ++mi) {
      const aiMesh& am = *ai->mMeshes[item.node->mMeshes[mi]];
      if (!(am.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;  // points and lines
      Mesh mesh;
      mesh.name = path + ": mesh '" + am.mName.C_Str() + "'";
      mesh.material = materialOf.empty() ? 0 : materialOf[am.mMaterialIndex];
      mesh.positions.reserve(am.mNumVertices);
      for (unsigned v = 0; v < am.mNumVertices; ++v) {
        const aiVector3D& p = am.mVertices[v];  // NaN/Inf: validateGeometry rejects them
        mesh.positions.push_back(glm::dvec3(item.toWorld * glm::dvec4(p.x, p.y, p.z, 1.0)));
      }
      for (unsigned f = 0; f < am.mNumFaces; ++f)
        if (am.mFaces[f].mNumIndices == 3)
          mesh.triangles.emplace_back(am.mFaces[f].mIndices[0], am.mFaces[f].mIndices[1],
                                      am.mFaces[f].mIndices[2]);
      if (materialOf.empty()) {
        Material fallback;
        fallback.name = "default";
        mesh.material = internMaterial(scene, fallback);
      }
      scene.meshes.push_back(std::move(mesh));
    }
  }
}

}  // namespace voxgi
