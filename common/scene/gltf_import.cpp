// glTF 2.0 geometry through tinygltf (Debian's libtinygltf-dev): it decodes the buffers (data:
// URIs, external .bin files, a GLB's BIN chunk) and voxgi reads the accessors it needs from them.
// Assimp 5.2.5 is not used for glTF: it imports only the materials a mesh uses, in the order it
// happens to load them, so its material indices cannot be matched with the file's.
#include <cstring>
#include <filesystem>
#include <limits>
#include <string_view>

#include "common/scene/tinygltf.h"

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/scene/gltf_authored.h"
#include "common/scene/gltf_import.h"

namespace voxgi {
namespace {

// Images are not decoded here: tinygltf would hand them to stb_image; textures are read by voxgi's
// own image readers.
bool keepImageUndecoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                        const unsigned char*, int, void*) {
  return true;
}

// Element `i` of an accessor as little-endian bytes: a pointer to its first component, each
// element checked to lie inside its buffer view (a byteStride can reach past what count * size
// does).
class AccessorReader {
 public:
  AccessorReader(const std::string& file, const tinygltf::Model& model, int index,
                 const std::string& field)
      : field_(file + ": accessors[" + std::to_string(index) + "] (" + field + ")") {
    if (index < 0 || size_t(index) >= model.accessors.size()) fail("names no accessor");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) fail("sparse accessors are not supported");
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
      fail("has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) fail("names no buffer");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    componentType = a.componentType;
    components = size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
    const int componentBytes = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (componentBytes <= 0 || components == 0 || components > 16) fail("unknown type");
    elementBytes_ = components * size_t(componentBytes);
    stride_ = view.byteStride != 0 ? view.byteStride : elementBytes_;
    count = a.count;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
      fail("its buffer view runs past its buffer");
    if (count > 0) {
      const long double end = (long double)a.byteOffset + (long double)(count - 1) * stride_ +
                              (long double)elementBytes_;
      if (end > (long double)view.byteLength) fail("runs past the end of its buffer view");
    }
    base_ = data.data() + view.byteOffset + a.byteOffset;
  }
  [[noreturn]] void fail(const std::string& reason) const { throw InputError(field_, "", reason); }
  const unsigned char* element(size_t i) const { return base_ + i * stride_; }
  // Component `c` of element `i` as an unsigned integer (UNSIGNED_BYTE, _SHORT or _INT).
  uint32_t index(size_t i) const {
    const unsigned char* p = element(i);
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return uint32_t(p[0]) | uint32_t(p[1]) << 8;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }
    fail("indices must be unsigned bytes, shorts or ints");
  }
  glm::vec3 vec3(size_t i) const {
    float v[3];
    std::memcpy(v, element(i), sizeof v);  // glTF is little-endian, as are voxgi's targets
    return {v[0], v[1], v[2]};
  }

  int componentType = 0;
  size_t components = 0;
  size_t count = 0;

 private:
  std::string field_;
  const unsigned char* base_ = nullptr;
  size_t elementBytes_ = 0, stride_ = 0;
};

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
tinygltf::Model loadModel(const std::string& path, const std::string& bytes) {
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
  loader.SetImageLoader(keepImageUndecoded, nullptr);
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

}  // namespace

MeshFileExtras importGltf(Scene& scene, const std::string& path, const GltfFile& file,
                          const glm::dmat4& transform,
                          const std::optional<uint32_t>& materialOverride) {
  const GltfAuthored authored = readGltfAuthored(path, file.json, transform);
  const tinygltf::Model model = loadModel(path, file.bytes);
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
          index = uint32_t(scene.materials.size());
          scene.materials.push_back(authored.materials[size_t(material)]);
        }
        mesh.material = *index;
      } else {
        throw InputError(path,
                         "meshes[" + std::to_string(instance.mesh) + "].primitives[" +
                             std::to_string(k) + "].material",
                         "names no material");
      }
      scene.meshes.push_back(std::move(mesh));
    }
  }
  return authored.extras;
}

}  // namespace voxgi
