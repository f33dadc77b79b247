// glTF 2.0 geometry through tinygltf (Debian's libtinygltf-dev): it decodes the buffers (data:
// URIs, external .bin files, a GLB's BIN chunk) and voxgi reads the accessors it needs from them.
// Assimp 5.2.5 is not used for glTF: it imports only the materials a mesh uses, in the order it
// happens to load them, so its material indices cannot be matched with the file's.
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <string_view>

#include "common/scene_io/tinygltf.h"

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/io/texture_read.h"
#include "common/scene_io/gltf_accessor.h"
#include "common/scene_io/gltf_animation.h"
#include "common/scene_io/gltf_authored.h"
#include "common/scene_io/gltf_import.h"

namespace voxgi {
namespace {

// The bytes of the images tinygltf read from a uri (a file next to the glTF, or a data: URI), by
// image index; they are decoded by voxgi's texture readers, not by tinygltf's stb_image. An image
// in a buffer view is read from the buffer (checked by checkGltf) when a material uses it.
bool keepImageBytes(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void* images) {
  if (image->bufferView < 0 && size > 0)
    (*static_cast<std::map<int, std::string>*>(images))[index].assign(
        reinterpret_cast<const char*>(bytes), size_t(size));
  return true;
}

// tinygltf's file access, through voxgi's input checks (a regular file, read whole); paths are
// taken as written, never expanded.
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void*) {
  try {
    const std::string bytes = readInputFile(path, "", "glTF buffer or image file");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    *err = e.what();
    return false;
  }
}

// The model tinygltf parses from the checked bytes; external buffers are read through voxgi's
// file access, next to the glTF file.
tinygltf::Model loadModel(const std::string& path, const std::string& bytes,
                          std::map<int, std::string>& images) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    throw InputError(path, "", "larger than 4 GiB, tinygltf's limit");
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({[](const std::string& file, void*) {
                           std::error_code ec;
                           return std::filesystem::is_regular_file(file, ec);
                         },
                         [](const std::string& file, void*) { return file; }, readWholeFile,
                         [](std::string*, const std::string&, const std::vector<unsigned char>&,
                            void*) { return false; },
                         nullptr});
  loader.SetImageLoader(keepImageBytes, &images);
  tinygltf::Model model;
  std::string err, warn;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const auto length = static_cast<unsigned int>(bytes.size());
  const bool ok = bytes.starts_with("glTF")
                      ? loader.LoadBinaryFromMemory(
                            &model, &err, &warn,
                            reinterpret_cast<const unsigned char*>(bytes.data()), length, dir)
                      : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, dir);
  if (!ok) {
    const std::string first = err.substr(0, err.find('\n'));
    throw InputError(path, "", "cannot import: " + (first.empty() ? "tinygltf failed" : first));
  }
  return model;
}

// The triangles of one primitive (TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN), in world space.
Mesh primitiveMesh(const std::string& path, const tinygltf::Model& model, size_t meshIndex,
                   size_t primitive, const glm::dmat4& toWorld) {
  const tinygltf::Mesh& gm = model.meshes[meshIndex];
  const tinygltf::Primitive& p = gm.primitives[primitive];
  const std::string where =
      "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primitive) + "]";
  Mesh mesh;
  mesh.name = path + ": mesh '" + (gm.name.empty() ? where : gm.name) + "'";
  const auto position = p.attributes.find("POSITION");
  if (position == p.attributes.end()) throw InputError(path, where, "has no POSITION");
  const AccessorReader positions(path, model, position->second, where + " POSITION");
  if (positions.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || positions.components != 3)
    positions.fail("POSITION must be float VEC3 (KHR_mesh_quantization is not supported)");
  mesh.positions.reserve(positions.count);
  for (size_t v = 0; v < positions.count; ++v) {
    const glm::vec3 q = positions.vec3(v);  // NaN/Inf: validateGeometry rejects them
    mesh.positions.push_back(glm::dvec3(toWorld * glm::dvec4(glm::dvec3(q), 1.0)));
  }
  const auto texcoord = p.attributes.find("TEXCOORD_0");
  if (texcoord != p.attributes.end()) {
    const AccessorReader uv(path, model, texcoord->second, where + " TEXCOORD_0");
    const int type = uv.componentType;
    if (uv.components != 2 ||
        (type != TINYGLTF_COMPONENT_TYPE_FLOAT && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
      uv.fail("TEXCOORD_0 must be VEC2 of floats or normalized unsigned bytes or shorts");
    if (uv.count != positions.count)
      uv.fail(std::to_string(uv.count) + " texture coordinates for " +
              std::to_string(positions.count) + " positions");
    mesh.texcoords.reserve(uv.count);
    for (size_t v = 0; v < uv.count; ++v) mesh.texcoords.push_back(uv.texcoord(v));
  }
  std::vector<uint32_t> order;
  if (p.indices >= 0) {
    const AccessorReader indices(path, model, p.indices, where + " indices");
    if (indices.components != 1) indices.fail("indices must be SCALAR");
    order.reserve(indices.count);
    for (size_t i = 0; i < indices.count; ++i) {
      order.push_back(indices.index(i));
      if (order.back() >= positions.count)
        indices.fail("index " + std::to_string(order.back()) + " of " +
                     std::to_string(positions.count) + " vertices");
    }
  } else {
    for (size_t i = 0; i < positions.count; ++i) order.push_back(uint32_t(i));
  }
  const size_t n = order.size();
  if (p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == -1) {
    for (size_t i = 0; i + 2 < n; i += 3)
      mesh.triangles.emplace_back(order[i], order[i + 1], order[i + 2]);
  } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < n; ++i)  // every other triangle reversed, keeping the winding
      mesh.triangles.emplace_back(order[i], order[i + 1 + (i & 1)], order[i + 2 - (i & 1)]);
  } else if (p.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 1; i + 1 < n; ++i)
      mesh.triangles.emplace_back(order[0], order[i], order[i + 1]);
  }
  return mesh;
}

// The scene texture of the file's texture `index`: its image decoded on first use, from the bytes
// tinygltf read or from its buffer view.
uint32_t gltfTexture(Scene& scene, const std::string& path, const GltfAuthored& authored,
                     const tinygltf::Model& model, const std::map<int, std::string>& images,
                     size_t index) {
  const GltfTexture& t = authored.textures[index];
  const std::string field = "images[" + std::to_string(t.image) + "]";
  return scene.textures.texture(path + ": " + field, t.wrapS, t.wrapT, [&] {
    const tinygltf::Image& image = model.images.at(t.image);
    if (image.bufferView >= 0) {
      const tinygltf::BufferView& view = model.bufferViews.at(size_t(image.bufferView));
      const std::vector<unsigned char>& data = model.buffers.at(size_t(view.buffer)).data;
      if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw InputError(path, field, "its buffer view runs past its buffer");
      return decodeTexture(
          std::string_view(reinterpret_cast<const char*>(data.data()) + view.byteOffset,
                           view.byteLength),
          path, field);
    }
    const auto bytes = images.find(int(t.image));
    if (bytes != images.end()) return decodeTexture(bytes->second, path, field);
    // tinygltf only warns when it cannot read an image file: read it here for the error's sake.
    if (image.uri.starts_with("data:")) throw InputError(path, field, "holds no image data");
    return readTexture(
        (std::filesystem::path(path).parent_path() / image.uri).lexically_normal().string(), path,
        field);
  });
}

}  // namespace

MeshFileExtras importGltf(Scene& scene, const std::string& path, const GltfFile& file,
                          const glm::dmat4& transform,
                          const std::optional<uint32_t>& materialOverride) {
  GltfAuthored authored = readGltfAuthored(path, file.json, transform);
  std::map<int, std::string> images;
  const tinygltf::Model model = loadModel(path, file.bytes, images);
  readGltfAnimations(path, model, authored);
  NodeMotion imported;
  imported.rest = transform;
  // A node path: the import transform, then the file's nodes from the root.
  const auto nodePath = [&](const std::vector<size_t>& nodes) {
    NodePath p{{imported}};
    for (const size_t n : nodes) p.nodes.push_back(authored.nodes[n]);
    return p;
  };
  MeshFileExtras extras = authored.extras;
  for (const std::vector<size_t>& nodes : authored.lightNodes)
    extras.lightPaths.push_back(nodePath(nodes));
  for (size_t c = 0; c < extras.cameras.size(); ++c)
    extras.cameras[c].path = nodePath(authored.cameraNodes[c]);
  std::vector<std::optional<uint32_t>> materialOf(authored.materials.size());
  for (const GltfMeshInstance& instance : authored.meshes) {
    if (instance.mesh >= model.meshes.size())
      throw InputError(path, "nodes",
                       "a node names mesh " + std::to_string(instance.mesh) + " of " +
                           std::to_string(model.meshes.size()));
    for (size_t k = 0; k < model.meshes[instance.mesh].primitives.size(); ++k) {
      const int material = model.meshes[instance.mesh].primitives[k].material;
      const int mode = model.meshes[instance.mesh].primitives[k].mode;
      if (mode >= 0 && mode < TINYGLTF_MODE_TRIANGLES) continue;  // points and lines
      Mesh mesh = primitiveMesh(path, model, instance.mesh, k, instance.toWorld);
      if (materialOverride) {
        mesh.material = *materialOverride;
      } else if (material < 0) {  // glTF's default is a white metal; voxgi's, as for OBJ, grey
        mesh.material = defaultMaterial(scene);
      } else if (size_t(material) < materialOf.size()) {
        // Each of the file's materials once, in the order its meshes use them; not merged with
        // another of the same name (glTF names need not be unique).
        std::optional<uint32_t>& index = materialOf[size_t(material)];
        if (!index) {
          Material m = authored.materials[size_t(material)];
          const GltfMaterialTextures& textures = authored.materialTextures[size_t(material)];
          if (textures.albedo)
            m.albedoTexture = gltfTexture(scene, path, authored, model, images, *textures.albedo);
          if (textures.emission)
            m.emissionTexture =
                gltfTexture(scene, path, authored, model, images, *textures.emission);
          index = uint32_t(scene.materials.size());
          scene.materials.push_back(std::move(m));
        }
        mesh.material = *index;
      } else {
        throw InputError(path,
                         "meshes[" + std::to_string(instance.mesh) + "].primitives[" +
                             std::to_string(k) + "].material",
                         "names no material");
      }
      extras.meshPaths.push_back({scene.meshes.size(), 1, nodePath(instance.nodes)});
      scene.meshes.push_back(std::move(mesh));
    }
  }
  return extras;
}

}  // namespace voxgi
