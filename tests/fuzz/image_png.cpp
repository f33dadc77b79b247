// Fuzz target: a .png image through readImage (references, masks and compare's inputs).
#include "common/error.h"
#include "common/image_io.h"
#include "tests/fuzz/fuzz_target.h"

int voxgi::fuzz::image_png(const uint8_t* data, size_t size) {
  const std::string path = voxgi::fuzz::writeInput(data, size, "input.png");
  try {
    voxgi::readImage(path);
  } catch (const voxgi::InputError&) {
  }
  return 0;
}
