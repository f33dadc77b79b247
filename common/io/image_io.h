// Images: EXR (linear float RGB, the primary output) and PNG (preview: exposure, clamp to [0,1],
// sRGB transfer curve, 8 bits).
#pragma once

#include <string>
#include <vector>

#include "common/image.h"

namespace voxgi {

// Writes through common/io/output_file.h: complete or not at all, the previous file kept on
// failure. Throws InputError naming the file.
void writeExr(const std::string& path, const Image& image);
Image readExr(const std::string& path);
// An EXR, or a PNG (8-bit sRGB decoded to linear) when the name ends in .png.
Image readImage(const std::string& path);
void writePng(const std::string& path, const Image& image, float exposure = 1.0f);
// An 8-bit sRGB image as it is (row-major RGB), through a temporary like the others.
void writeRgb8Png(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb);

}  // namespace voxgi
