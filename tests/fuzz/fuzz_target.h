// What every fuzz target shares: the input written to a file of the right extension in a private
// folder (voxgi's loaders read files), and the rule that only InputError may leave a loader —
// anything else (a crash, another exception, a hang past -timeout, memory past -rss_limit_mb) is a
// finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace voxgi::fuzz {

// The folder the target writes its input into (created once per process).
const std::string& workFolder();

// Writes the input to workFolder()/name and returns the path.
std::string writeInput(const uint8_t* data, size_t size, const std::string& name);

// The targets (tests/fuzz/file_targets.cpp, scene_json.cpp), each libFuzzer's
// LLVMFuzzerTestOneInput in its own binary (tests/fuzz/CMakeLists.txt) and all of them in the
// replay tool.
#define VOXGI_FUZZ_TARGETS(X) \
  X(mesh_obj)                 \
  X(mesh_ply)                 \
  X(mesh_gltf) X(mesh_glb) X(scene_json) X(image_exr) X(image_png) X(texture_png) X(texture_jpeg)
#define VOXGI_DECLARE_TARGET(name) int name(const uint8_t* data, size_t size);
VOXGI_FUZZ_TARGETS(VOXGI_DECLARE_TARGET)
#undef VOXGI_DECLARE_TARGET

}  // namespace voxgi::fuzz
