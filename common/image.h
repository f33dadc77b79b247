// An image of linear RGB floats, as renderers produce it; its files are common/io/image_io.h's.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace voxgi {

struct Image {
  int width = 0, height = 0;
  std::vector<glm::vec3> pixels;  // row-major, top row first
  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), glm::vec3(0.0f)) {}
  glm::vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace voxgi
