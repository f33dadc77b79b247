// Images: EXR (linear float RGB, the primary output) and PNG (preview: exposure, clamp to [0,1],
// sRGB transfer curve, 8 bits).
#pragma once

#include <string>
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

// Writes through common/output_file.h: complete or not at all, the previous file kept on failure.
// Throws InputError naming the file.
void writeExr(const std::string& path, const Image& image);
Image readExr(const std::string& path);
// An EXR, or a PNG (8-bit sRGB decoded to linear) when the name ends in .png.
Image readImage(const std::string& path);
void writePng(const std::string& path, const Image& image, float exposure = 1.0f);
// An 8-bit sRGB image as it is (row-major RGB), through a temporary like the others.
void writeRgb8Png(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb);

// sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1].
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace voxgi
