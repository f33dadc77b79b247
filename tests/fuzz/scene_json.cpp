// Fuzz target: a JSON scene (next to a one-triangle mesh.obj it may reference) through loadScene
// and voxel cone tracing's planner.
#include <fstream>

#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "common/technique.h"
#include "tests/fuzz/fuzz_target.h"

int voxgi::fuzz::scene_json(const uint8_t* data, size_t size) {
  static const bool mesh = [] {
    std::ofstream(voxgi::fuzz::workFolder() + "/mesh.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    return true;
  }();
  (void)mesh;
  const std::string path = voxgi::fuzz::writeInput(data, size, "input.json");
  try {
    const voxgi::Scene scene = voxgi::loadScene(path);
    const voxgi::Technique& vct = voxgi::findTechnique("vct");
    vct.plan(scene, voxgi::resolveSettings(vct, scene.settings, scene.file, "default", {}));
  } catch (const voxgi::InputError&) {
  }
  return 0;
}
