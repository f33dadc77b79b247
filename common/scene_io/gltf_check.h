// A check of a glTF 2.0 file (.gltf JSON or .glb binary) before Assimp reads it: Assimp allocates
// what a file's buffers and accessors declare (a 2 KB .glb can ask for 4 GB). Every buffer, view
// and accessor must fit in the data the file really has — its BIN chunk, a data: URI, or an
// external file next to it — so what tinygltf allocates is bounded by the files' sizes. Throws
// InputError naming the file and the field (buffers[0].byteLength, accessors[3].count, ...). A
// glTF 1.0 file is refused as such.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace voxgi {

// A checked glTF file: its bytes as read (tinygltf parses these, not the file again, so what it
// reads is what was checked) and its JSON document (a GLB's JSON chunk).
struct GltfFile {
  std::string bytes;
  nlohmann::json json;
};

GltfFile checkGltf(const std::string& path);

}  // namespace voxgi
