// The fuzz targets that hand one file to one loader: a bare mesh file to loadScene (Assimp behind
// voxgi's checks), an image to readImage (references, masks and compare's inputs), a texture to
// readTexture and into a texture pool (its mip levels).
#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/texture_read.h"
#include "common/scene_io/scene_load.h"
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
void texture(const std::string& path) {
  TexturePool pool;
  pool.texture(path, shared::kWrapRepeat, shared::kWrapRepeat,
               [&] { return readTexture(path, "fuzz input", "texture"); });
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
VOXGI_FILE_TARGET(texture_png, "input.png", texture)
VOXGI_FILE_TARGET(texture_jpeg, "input.jpg", texture)
#undef VOXGI_FILE_TARGET

}  // namespace voxgi::fuzz
