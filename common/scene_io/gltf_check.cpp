#include "common/scene_io/gltf_check.h"

#include <cstdint>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/input_file.h"

namespace voxgi {
namespace {

using nlohmann::json;

constexpr const char* kGltf1 = "glTF 1.0 is not supported (voxgi reads glTF 2.0)";

// glTF 2.0 requires asset.version; a 1.0 file (no version, or "1.x") is named as such before its
// other fields, laid out differently, fail a 2.0 check with a message that misleads.
void checkVersion(const std::string& path, const json& doc) {
  const auto asset = doc.find("asset");
  const json* version = nullptr;
  if (asset != doc.end() && asset->is_object() && asset->contains("version"))
    version = &asset->at("version");
  if (version == nullptr || !version->is_string() || version->get<std::string>().starts_with("1"))
    throw InputError(path, "asset.version", kGltf1);
  if (!version->get<std::string>().starts_with("2."))
    throw InputError(path, "asset.version",
                     "glTF " + version->get<std::string>() + " is not supported (voxgi reads 2.0)");
}

uint32_t le32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(bytes[at + size_t(i)]);
  return v;
}

// An unsigned integer member, or `fallback` when absent; InputError otherwise.
uint64_t count(const std::string& path, const json& object, const char* key,
               const std::string& field, uint64_t fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned())
    throw InputError(path, field + "." + key, "must be a non-negative integer");
  return it->get<uint64_t>();
}

// Bytes a data: URI holds (base64 decoded), or the size of the file it names.
uint64_t uriBytes(const std::string& path, const std::string& uri, const std::string& field) {
  if (uri.rfind("data:", 0) == 0) {
    const size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.find(";base64", 0) > comma)
      throw InputError(path, field, "only base64 data: URIs are supported");
    const size_t chars = uri.size() - comma - 1;
    return chars / 4 * 3;  // an upper bound; padding only makes it smaller
  }
  const std::filesystem::path file = std::filesystem::path(path).parent_path() / uri;
  try {
    return requireInputFile(file.string(), "", "glTF buffer file");
  } catch (const InputError& e) {  // named after the glTF file and its field, then the buffer's
    throw InputError(path, field, e.what());
  }
}

size_t componentBytes(uint64_t componentType) {
  switch (componentType) {
    case 5120:  // BYTE
    case 5121:  // UNSIGNED_BYTE
      return 1;
    case 5122:  // SHORT
    case 5123:  // UNSIGNED_SHORT
      return 2;
    case 5125:  // UNSIGNED_INT
    case 5126:  // FLOAT
      return 4;
  }
  return 0;
}

size_t typeComponents(const std::string& type) {
  static const std::pair<const char*, size_t> types[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
  for (const auto& [name, n] : types)
    if (type == name) return n;
  return 0;
}

// The document's JSON text and, for a GLB, its BIN chunk's size, from the container's header.
struct GltfContainer {
  std::string text;
  bool glb = false;
  uint64_t binChunk = 0;  // bytes of the GLB's BIN chunk
};

GltfContainer readContainer(const std::string& path, const std::string& bytes) {
  GltfContainer c;
  c.glb = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (!c.glb) {
    c.text = bytes;
    return c;
  }
  if (bytes.size() < 20) throw InputError(path, "header", "shorter than a GLB header");
  if (le32(bytes, 4) == 1) throw InputError(path, "header", kGltf1);
  if (le32(bytes, 4) != 2) throw InputError(path, "header", "not glTF version 2");
  if (le32(bytes, 8) != bytes.size())
    throw InputError(path, "header",
                     "declares " + std::to_string(le32(bytes, 8)) + " bytes, the file has " +
                         std::to_string(bytes.size()));
  size_t at = 12;
  for (int chunk = 0; at + 8 <= bytes.size(); ++chunk) {
    const uint64_t length = le32(bytes, at);
    const std::string type = bytes.substr(at + 4, 4);
    if (at + 8 + length > bytes.size())
      throw InputError(path, "chunk " + std::to_string(chunk), "runs past the end of the file");
    if (chunk == 0 && type != std::string("JSON", 4))
      throw InputError(path, "chunk 0", "the first chunk must be JSON");
    if (chunk == 0) c.text = bytes.substr(at + 8, length);
    if (chunk == 1 && type == std::string("BIN\0", 4)) c.binChunk = length;
    at += 8 + length;
  }
  return c;
}

// The top-level array `key` (empty when absent).
json topArray(const std::string& path, const json& doc, const char* key) {
  const auto it = doc.find(key);
  if (it == doc.end()) return json::array();
  if (!it->is_array()) throw InputError(path, key, "must be an array");
  return *it;
}

// Each buffer's declared length, checked against its file or the BIN chunk.
std::vector<uint64_t> checkBuffers(const std::string& path, const json& doc,
                                   const GltfContainer& c) {
  std::vector<uint64_t> bufferBytes;
  const json buffers = topArray(path, doc, "buffers");
  for (size_t i = 0; i < buffers.size(); ++i) {
    const std::string field = "buffers[" + std::to_string(i) + "]";
    if (!buffers[i].is_object()) throw InputError(path, field, "must be an object");
    const uint64_t length = count(path, buffers[i], "byteLength", field, 0);
    const auto uri = buffers[i].find("uri");
    uint64_t available = c.binChunk;
    if (uri != buffers[i].end()) {
      if (!uri->is_string()) throw InputError(path, field + ".uri", "must be a string");
      available = uriBytes(path, uri->get<std::string>(), field + ".uri");
    } else if (!c.glb || i != 0) {
      throw InputError(path, field, "has no uri (only a GLB's first buffer may use its BIN chunk)");
    }
    if (length > available)
      throw InputError(
          path, field + ".byteLength",
          std::to_string(length) + " bytes declared, " + std::to_string(available) + " available");
    bufferBytes.push_back(length);
  }
  return bufferBytes;
}

// Each buffer view's length, checked to lie inside its buffer.
std::vector<uint64_t> checkViews(const std::string& path, const json& doc,
                                 const std::vector<uint64_t>& bufferBytes) {
  std::vector<uint64_t> viewBytes;
  const json views = topArray(path, doc, "bufferViews");
  for (size_t i = 0; i < views.size(); ++i) {
    const std::string field = "bufferViews[" + std::to_string(i) + "]";
    if (!views[i].is_object()) throw InputError(path, field, "must be an object");
    const uint64_t buffer = count(path, views[i], "buffer", field, ~0ull);
    const uint64_t offset = count(path, views[i], "byteOffset", field, 0);
    const uint64_t length = count(path, views[i], "byteLength", field, 0);
    if (buffer >= bufferBytes.size()) throw InputError(path, field + ".buffer", "names no buffer");
    if (offset > bufferBytes[buffer] || length > bufferBytes[buffer] - offset)
      throw InputError(path, field, "runs past the end of buffers[" + std::to_string(buffer) + "]");
    viewBytes.push_back(length);
  }
  return viewBytes;
}

// Each accessor's elements inside its view (or, without one, no more than the file has bytes).
void checkAccessors(const std::string& path, const json& doc, uint64_t fileBytes,
                    const std::vector<uint64_t>& viewBytes) {
  const json accessors = topArray(path, doc, "accessors");
  for (size_t i = 0; i < accessors.size(); ++i) {
    const std::string field = "accessors[" + std::to_string(i) + "]";
    const json& a = accessors[i];
    if (!a.is_object()) throw InputError(path, field, "must be an object");
    const uint64_t n = count(path, a, "count", field, 0);
    const size_t component = componentBytes(count(path, a, "componentType", field, 0));
    const auto type = a.find("type");
    const size_t components =
        type != a.end() && type->is_string() ? typeComponents(type->get<std::string>()) : 0;
    if (component == 0 || components == 0)
      throw InputError(path, field, "unknown componentType or type");
    if (!a.contains("bufferView")) {
      // Sparse or zero-filled: Assimp still allocates count elements; bound them by the file.
      if (n > fileBytes)
        throw InputError(path, field + ".count", "more elements than the file has bytes");
      continue;
    }
    const uint64_t view = count(path, a, "bufferView", field, 0);
    if (view >= viewBytes.size()) throw InputError(path, field + ".bufferView", "names no view");
    const uint64_t offset = count(path, a, "byteOffset", field, 0);
    const long double need =
        static_cast<long double>(offset) + static_cast<long double>(n) * component * components;
    if (need > static_cast<long double>(viewBytes[view]))
      throw InputError(path, field,
                       "needs more bytes than bufferViews[" + std::to_string(view) + "] holds");
  }
}

}  // namespace

GltfFile checkGltf(const std::string& path) {
  std::string bytes = readInputFile(path, "", "glTF file");
  const GltfContainer container = readContainer(path, bytes);
  json doc;
  try {
    doc = json::parse(container.text);
  } catch (const json::exception& e) {
    throw InputError(path, "", std::string("malformed glTF JSON: ") + e.what());
  }
  if (!doc.is_object()) throw InputError(path, "", "not a glTF document (no top-level object)");
  checkVersion(path, doc);
  const std::vector<uint64_t> bufferBytes = checkBuffers(path, doc, container);
  checkAccessors(path, doc, bytes.size(), checkViews(path, doc, bufferBytes));
  return {std::move(bytes), std::move(doc)};
}

}  // namespace voxgi
