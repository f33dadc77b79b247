// The fuzz targets that hand one file to one loader: a bare mesh file to loadScene (Assimp behind
// voxgi's checks), an image to readImage (references, masks and compare's inputs).
#include "common/error.h"
#include "common/io/image_io.h"
#include "common/scene/scene_load.h"
#include "tests/fuzz/fuzz_target.h"

namespace voxgi::fuzz {
namespace {

// Writes the input as `name` and loads it; only InputError may leave the loader.
template <class Load>
int loadFile(const uint8_t* data, size_t size, const char* name, const Load& load) {
  const std::string path = writeInput(data, size, name);
  try {
    load(path);
  } catch (const InputError&) {
  }
  return 0;
}

void scene(const std::string& path) {
  loadScene(path);
}
void image(const std::string& path) {
  readImage(path);
}

}  // namespace

// The target, the file name it writes (the extension picks the format), the loader.
#define VOXGI_FILE_TARGET(target, file, load) \
  int target(const uint8_t* d, size_t n) {    \
    return loadFile(d, n, file, load);        \
  }
VOXGI_FILE_TARGET(mesh_obj, "input.obj", scene)
VOXGI_FILE_TARGET(mesh_ply, "input.ply", scene)
VOXGI_FILE_TARGET(mesh_gltf, "input.gltf", scene)
VOXGI_FILE_TARGET(mesh_glb, "input.glb", scene)
VOXGI_FILE_TARGET(image_exr, "input.exr", image)
VOXGI_FILE_TARGET(image_png, "input.png", image)
#undef VOXGI_FILE_TARGET

}  // namespace voxgi::fuzz
