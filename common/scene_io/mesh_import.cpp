// Mesh files: OBJ/MTL and mesh PLY through Assimp, glTF through common/scene_io/gltf_import.h, each
// checked before it is read.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/io/texture_read.h"
#include "common/scene_io/gltf_check.h"
#include "common/scene_io/gltf_import.h"
#include "common/scene_io/ply_check.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {
namespace {

glm::vec3 color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                glm::vec3 fallback) {
  aiColor4D c;
  if (m.Get(key, type, index, c) == AI_SUCCESS) return {c.r, c.g, c.b};
  return fallback;
}

// An OBJ/MTL (or mesh PLY) material as Assimp reads it; glTF's come from
// common/scene_io/gltf_authored.h.
Material convertMaterial(const aiMaterial& m) {
  Material out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  out.albedo = color(m, AI_MATKEY_COLOR_DIFFUSE, out.albedo);
  out.specular = color(m, AI_MATKEY_COLOR_SPECULAR, out.specular);
  out.emission = color(m, AI_MATKEY_COLOR_EMISSIVE, out.emission);
  float shininess = 0.0f;
  if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS) out.shininess = shininess;
  return out;
}

// A sampler's wrap mode as Assimp reads it (OBJ's "-clamp on").
uint32_t wrapMode(const aiMaterial& m, aiTextureType type, const char* key) {
  int mode = aiTextureMapMode_Wrap;
  m.Get(key, unsigned(type), 0, mode);
  if (mode == aiTextureMapMode_Clamp || mode == aiTextureMapMode_Decal) return shared::kWrapClamp;
  if (mode == aiTextureMapMode_Mirror) return shared::kWrapMirror;
  return shared::kWrapRepeat;
}

// The texture of `type` (map_Kd, map_Ke) of an OBJ material, read from the file it names, next to
// the model file; kNoTexture when the material has none. Files written on Windows name their
// textures with backslashes (".\\skin.jpg" in Assimp's own spider.obj): where the name as written
// is no file, its backslashes are read as separators.
uint32_t assimpTexture(Scene& scene, const std::string& path, const aiMaterial& m,
                       aiTextureType type, const Material& material) {
  aiString file;
  if (m.GetTexture(type, 0, &file) != AI_SUCCESS) return shared::kNoTexture;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::string name = file.C_Str();
  std::error_code ec;
  if (!std::filesystem::exists(dir / name, ec)) std::replace(name.begin(), name.end(), '\\', '/');
  const std::string image = (dir / name).lexically_normal().string();
  const std::string field =
      "material '" + material.name + "' " + (type == aiTextureType_DIFFUSE ? "map_Kd" : "map_Ke");
  return scene.textures.texture(image, wrapMode(m, type, _AI_MATKEY_MAPPINGMODE_U_BASE),
                                wrapMode(m, type, _AI_MATKEY_MAPPINGMODE_V_BASE),
                                [&] { return readTexture(image, path, field); });
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

// Assimp picks an importer by content whatever the extension, so a file must be what its name says
// before Assimp sees it; a PLY is checked whole (common/scene_io/ply_check.h). Returns a glTF file
// as checked.
std::optional<GltfFile> checkMeshFileContent(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  std::ifstream in(path, std::ios::binary);
  char head[4] = {};
  in.read(head, 4);
  const std::string magic(head, size_t(in.gcount()));
  if (ext == ".ply") {
    checkPly(path);
  } else if (ext == ".glb") {
    if (magic != "glTF") throw InputError(path, "", "not a binary glTF file (no 'glTF' magic)");
    return checkGltf(path);
  } else if (ext == ".gltf") {
    char c = ' ';
    in.seekg(0);
    while (in.get(c) && std::isspace(static_cast<unsigned char>(c))) {
    }
    if (c != '{') throw InputError(path, "", "not a glTF file (JSON starting with '{')");
    return checkGltf(path);
  } else if (ext != ".obj") {
    throw InputError(path, "", "unknown mesh format '" + ext + "' (OBJ, glTF, GLB or PLY)");
  }
  return std::nullopt;
}

// OBJ and mesh PLY files through Assimp: the triangles of every node, in world space.
void importWithAssimp(Scene& scene, const std::string& path, const glm::dmat4& transform,
                      const std::optional<uint32_t>& materialOverride) {
  Assimp::Importer importer;
  // No degenerate-triangle removal here: the voxelizer handles them (and tests that it does).
  // ValidateDataStructure: Assimp's own check of indices, counts and references before voxgi
  // reads them; voxgi still checks what it uses (a root node, the material index).
  const aiScene* ai =
      importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                  aiProcess_SortByPType | aiProcess_JoinIdenticalVertices);
  if (ai == nullptr)
    throw InputError(path, "", std::string("cannot import: ") + importer.GetErrorString());
  if (ai->mRootNode == nullptr) throw InputError(path, "", "cannot import: no scene graph");
  std::vector<uint32_t> materialOf(ai->mNumMaterials);
  for (unsigned i = 0; i < ai->mNumMaterials; ++i)
    if (materialOverride) {
      materialOf[i] = *materialOverride;
    } else {
      Material material = convertMaterial(*ai->mMaterials[i]);
      material.albedoTexture =
          assimpTexture(scene, path, *ai->mMaterials[i], aiTextureType_DIFFUSE, material);
      material.emissionTexture =
          assimpTexture(scene, path, *ai->mMaterials[i], aiTextureType_EMISSIVE, material);
      materialOf[i] = internMaterial(scene, std::move(material));
    }

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
      if (!materialOf.empty() && am.mMaterialIndex >= materialOf.size())
        throw InputError(mesh.name, "material", "index out of range");
      mesh.material = materialOf.empty() ? 0 : materialOf[am.mMaterialIndex];
      mesh.positions.reserve(am.mNumVertices);
      for (unsigned v = 0; v < am.mNumVertices; ++v) {
        const aiVector3D& p = am.mVertices[v];  // NaN/Inf: validateGeometry rejects them
        mesh.positions.push_back(glm::dvec3(item.toWorld * glm::dvec4(p.x, p.y, p.z, 1.0)));
      }
      // OBJ's v points up from the image's last row; voxgi's, glTF's, down from its first.
      if (am.HasTextureCoords(0))
        for (unsigned v = 0; v < am.mNumVertices; ++v)
          mesh.texcoords.emplace_back(am.mTextureCoords[0][v].x, 1.0f - am.mTextureCoords[0][v].y);
      for (unsigned f = 0; f < am.mNumFaces; ++f)
        if (am.mFaces[f].mNumIndices == 3)
          mesh.triangles.emplace_back(am.mFaces[f].mIndices[0], am.mFaces[f].mIndices[1],
                                      am.mFaces[f].mIndices[2]);
      if (materialOf.empty()) mesh.material = defaultMaterial(scene);
      scene.meshes.push_back(std::move(mesh));
    }
  }
}

// A file without triangles, or whose every triangle is degenerate, would render as nothing, and a
// bare one would get a grid of zero size: refused.
void checkTriangles(const Scene& scene, const std::string& path, size_t meshesBefore) {
  size_t triangles = 0, withArea = 0;
  for (size_t m = meshesBefore; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    triangles += mesh.triangles.size();
    // Edges scaled to a largest component of 1 first, so a tiny mesh does not underflow to 0.
    const auto unitMax = [](const glm::dvec3& e) {
      const double largest = std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)});
      return largest > 0.0 ? e / largest : e;
    };
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3& a = mesh.positions[t.x];
      if (glm::cross(unitMax(mesh.positions[t.y] - a), unitMax(mesh.positions[t.z] - a)) !=
          glm::dvec3(0.0))
        ++withArea;
    }
  }
  if (triangles == 0) throw InputError(path, "", "no triangles (only points or lines, or nothing)");
  if (withArea == 0)
    throw InputError(path, "",
                     "every one of its " + std::to_string(triangles) +
                         " triangles has zero area (nothing to render)");
}

}  // namespace

MeshFileExtras importMeshFile(Scene& scene, const std::string& path, const glm::dmat4& transform,
                              const std::optional<uint32_t>& materialOverride) {
  requireInputFile(path, "", "mesh file");
  const std::optional<GltfFile> gltf = checkMeshFileContent(path);
  const size_t meshesBefore = scene.meshes.size();
  MeshFileExtras extras;
  if (gltf)
    extras = importGltf(scene, path, *gltf, transform, materialOverride);
  else
    importWithAssimp(scene, path, transform, materialOverride);
  checkTriangles(scene, path, meshesBefore);
  return extras;
}

}  // namespace voxgi
