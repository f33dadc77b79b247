// Fuzz target: a bare .glb mesh file through loadScene (Assimp behind voxgi's checks).
#include "common/error.h"
#include "common/scene_load.h"
#include "tests/fuzz/fuzz_target.h"

int voxgi::fuzz::mesh_glb(const uint8_t* data, size_t size) {
  const std::string path = voxgi::fuzz::writeInput(data, size, "input.glb");
  try {
    voxgi::loadScene(path);
  } catch (const voxgi::InputError&) {
  }
  return 0;
}
