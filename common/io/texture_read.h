// Texture images: PNG (libpng) and JPEG (libjpeg-turbo) decoded to 8-bit sRGB RGB, with their
// declared size checked against the limits, the file's own length and the available memory before
// any pixel is allocated (docs/robustness.md).
#pragma once

#include <string>
#include <string_view>

#include "common/texture.h"

namespace voxgi {

// Largest texture side voxgi decodes.
constexpr int kMaxTextureSide = 16384;

// Decodes PNG or JPEG bytes (told apart by their signature). `file` and `field` name where the
// bytes came from in the one-line InputError a bad image gets ("room.glb", "images[2]").
DecodedImage decodeTexture(std::string_view bytes, const std::string& file,
                           const std::string& field);

// The image file at `path`, as decodeTexture. Its errors name `referrer` (the model file that
// names the image) and `field` first, then the image: "spider.obj: material 'Skin' map_Kd:
// ./skin.jpg: cannot read JPEG: ...".
DecodedImage readTexture(const std::string& path, const std::string& referrer,
                         const std::string& field);

}  // namespace voxgi
