#include "common/texture.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/error.h"

namespace voxgi {

int mipLevelCount(int width, int height) {
  int levels = 1;
  for (int w = width, h = height; w > 1 || h > 1; w = std::max(1, w / 2), h = std::max(1, h / 2))
    ++levels;
  return levels;
}

uint64_t mipTexelCount(int width, int height) {
  uint64_t n = 0;
  for (int l = 0, w = width, h = height; l < mipLevelCount(width, height);
       ++l, w = std::max(1, w / 2), h = std::max(1, h / 2))
    n += uint64_t(w) * uint64_t(h);
  return n;
}

const std::array<float, 256>& srgbDecodeTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int c = 0; c < 256; ++c) {
      const double x = c / 255.0;
      t[size_t(c)] = float(x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

float uvPerLength(const glm::vec2 uv[3], double area) {
  const glm::dvec2 d1 = glm::dvec2(uv[1]) - glm::dvec2(uv[0]),
                   d2 = glm::dvec2(uv[2]) - glm::dvec2(uv[0]);
  const double uvArea = 0.5 * std::abs(d1.x * d2.y - d1.y * d2.x);
  return area > 0.0 ? static_cast<float>(std::sqrt(uvArea / area)) : 0.0f;
}

uint32_t srgbEncode(float linear) {
  const std::array<float, 256>& t = srgbDecodeTable();
  // The first code at or above the value, then whichever neighbour is nearer.
  const auto above = std::lower_bound(t.begin(), t.end(), linear);
  if (above == t.begin()) return 0;
  if (above == t.end()) return 255;
  const auto code = uint32_t(above - t.begin());
  return linear - t[code - 1] <= *above - linear ? code - 1 : code;
}

namespace {

uint32_t packRgb(uint32_t r, uint32_t g, uint32_t b) {
  return r | (g << 8) | (b << 16) | 0xff000000u;
}

// One level from the one above: each texel the mean of the 2x2 texels it covers, in linear space
// ((a + b) + (c + d) in that order, so a constant stays itself); an odd last row or column is
// dropped, as GL's box filter does.
std::vector<uint32_t> nextLevel(const uint32_t* above, int w, int h, int nw, int nh) {
  const std::array<float, 256>& decode = srgbDecodeTable();
  std::vector<uint32_t> level(size_t(nw) * size_t(nh));
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      const int x0 = std::min(2 * x, w - 1), x1 = std::min(2 * x + 1, w - 1);
      const int y0 = std::min(2 * y, h - 1), y1 = std::min(2 * y + 1, h - 1);
      const uint32_t q[4] = {
          above[size_t(y0) * size_t(w) + size_t(x0)], above[size_t(y0) * size_t(w) + size_t(x1)],
          above[size_t(y1) * size_t(w) + size_t(x0)], above[size_t(y1) * size_t(w) + size_t(x1)]};
      uint32_t out[3];
      for (int c = 0; c < 3; ++c) {
        const auto v = [&](int i) { return decode[(q[i] >> (8 * c)) & 255u]; };
        out[c] = srgbEncode(((v(0) + v(1)) + (v(2) + v(3))) * 0.25f);
      }
      level[size_t(y) * size_t(nw) + size_t(x)] = packRgb(out[0], out[1], out[2]);
    }
  return level;
}

// Appends an image's levels to the pool's texels; its record with repeat wrapping.
shared::TextureRecord appendImage(std::vector<uint32_t>& texels, const DecodedImage& image) {
  shared::TextureRecord r{};
  r.offset = uint32_t(texels.size());
  r.width = image.width;
  r.height = image.height;
  r.levels = mipLevelCount(image.width, image.height);
  r.wrapS = r.wrapT = shared::kWrapRepeat;
  texels.reserve(texels.size() + mipTexelCount(image.width, image.height));
  for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i)
    texels.push_back(packRgb(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]));
  size_t levelStart = r.offset;
  for (int l = 1, w = image.width, h = image.height; l < r.levels; ++l) {
    const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
    const std::vector<uint32_t> next = nextLevel(texels.data() + levelStart, w, h, nw, nh);
    levelStart = texels.size();
    texels.insert(texels.end(), next.begin(), next.end());
    w = nw;
    h = nh;
  }
  return r;
}

}  // namespace

uint32_t TexturePool::texture(const std::string& name, uint32_t wrapS, uint32_t wrapT,
                              const std::function<DecodedImage()>& decode) {
  std::optional<shared::TextureRecord> image;
  for (size_t i = 0; i < textures.size(); ++i) {
    if (names[i] != name) continue;
    if (textures[i].wrapS == wrapS && textures[i].wrapT == wrapT) return uint32_t(i);
    image = textures[i];
  }
  if (!image) {
    const DecodedImage decoded = decode();
    if (texels.size() + mipTexelCount(decoded.width, decoded.height) > UINT32_MAX)
      throw InputError(name, "", "the scene's textures hold more than 2^32 texels");
    image = appendImage(texels, decoded);
  }
  shared::TextureRecord r = *image;
  r.wrapS = wrapS;
  r.wrapT = wrapT;
  textures.push_back(r);
  names.push_back(name);
  return uint32_t(textures.size() - 1);
}

}  // namespace voxgi
