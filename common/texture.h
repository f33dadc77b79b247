// Textures in memory: every image of a scene decoded once into one pool of 8-bit sRGB texels with
// its mip levels, and the textures (an image and a sampler's wrap modes) that materials name. The
// pool is what the GPU uploads and what the CPU kernels read through TextureAccess, so both sample
// through shaders/shared/texture_kernel.h from the same words (docs/textures.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "shaders/shared/texture_kernel.h"

namespace voxgi {

// A decoded image before it joins a pool: level 0 only, RGB as 8-bit sRGB codes.
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, row 0 at v = 0 (the top of the file's image)
};

// Level count of a full mip chain down to 1x1, and the texels of all its levels.
int mipLevelCount(int width, int height);
uint64_t mipTexelCount(int width, int height);

// The linear value of every 8-bit sRGB code (IEC 61966-2-1, computed in double and rounded once),
// and the code whose value is nearest a linear value (ties to the lower code).
const std::array<float, 256>& srgbDecodeTable();
uint32_t srgbEncode(float linear);

// How many uv units one unit of length on a triangle covers, sqrt(uv area / area), for a triangle
// of `area` square units with texture coordinates uv: the scale from a filter's width on the
// surface to its footprint in the texture (0 for a degenerate triangle).
float uvPerLength(const glm::vec2 uv[3], double area);

struct TexturePool {
  std::vector<uint32_t> texels;                 // RGBA8 words of every image's levels
  std::vector<shared::TextureRecord> textures;  // indexed by Material::albedoTexture, ...
  std::vector<std::string> names;               // per texture: its image's file, for messages

  // The texture of image `name` (a file, or "model.glb: images[2]") with these wrap modes: added
  // on first use, its image decoded by `decode` the first time the name is seen and stored with
  // its mip chain (box-filtered in linear space); later uses share the image's texels.
  uint32_t texture(const std::string& name, uint32_t wrapS, uint32_t wrapT,
                   const std::function<DecodedImage()>& decode);
  uint64_t bytes() const { return texels.size() * 4 + textures.size() * sizeof(textures[0]); }
  bool empty() const { return textures.empty(); }
};

// The CPU side of texture_kernel.h's FETCH accessor.
struct TextureAccess {
  const TexturePool& pool;
  uint32_t textureWord(uint32_t i) const { return pool.texels[i]; }
  float srgbDecode(uint32_t code) const { return srgbDecodeTable()[code]; }
  shared::TextureRecord textureRecord(uint32_t i) const { return pool.textures[i]; }
};

}  // namespace voxgi
