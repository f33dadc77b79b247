#include "common/io/texture_read.h"

#include <memory>

// PNG through libpng's simplified API (as common/io/image_io.cpp) and JPEG through TurboJPEG, the
// API of libjpeg-turbo that reports errors by return value (libjpeg's own API needs setjmp and
// longjmp through C++ frames).
#include <png.h>
#include <turbojpeg.h>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/memory.h"

namespace voxgi {

namespace {

std::string sizeText(uint64_t w, uint64_t h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

// The limits every texture meets before its pixels are allocated: a side in 1..kMaxTextureSide,
// and its level 0 (the RGB being decoded) and mip chain (RGBA words) within the available memory.
void checkTextureSize(uint64_t w, uint64_t h, const std::string& file, const std::string& field) {
  if (w < 1 || h < 1 || w > uint64_t(kMaxTextureSide) || h > uint64_t(kMaxTextureSide))
    throw InputError(file, field,
                     "size " + sizeText(w, h) + " is outside 1.." +
                         std::to_string(kMaxTextureSide) + " per side");
  requireMemory(w * h * 3 + mipTexelCount(int(w), int(h)) * 4, "the texture", file, field);
}

DecodedImage decodePng(std::string_view bytes, const std::string& file, const std::string& field) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto release = [](png_image* p) { png_image_free(p); };
  std::unique_ptr<png_image, decltype(release)> guard(&png, release);
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()))
    throw InputError(file, field, std::string("cannot read PNG: ") + png.message);
  checkTextureSize(png.width, png.height, file, field);
  // Deflate expands at most 1032:1, and a row holds at least a filter byte and one bit per pixel:
  // a header that declares more than the bytes can hold is refused before anything is allocated.
  const uint64_t leastRawBytes = uint64_t(png.height) * (1 + (uint64_t(png.width) + 7) / 8);
  if (leastRawBytes > 1032 * uint64_t(bytes.size()))
    throw InputError(file, field,
                     "size " + sizeText(png.width, png.height) + " cannot be compressed into " +
                         std::to_string(bytes.size()) + " bytes (truncated or corrupt)");
  png.format = PNG_FORMAT_RGB;  // 8-bit sRGB whatever the file's colour type and depth
  DecodedImage image{int(png.width), int(png.height), {}};
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr))
    throw InputError(file, field, std::string("cannot read PNG: ") + png.message);
  return image;
}

DecodedImage decodeJpeg(std::string_view bytes, const std::string& file, const std::string& field) {
  const auto release = [](void* h) { tjDestroy(h); };
  std::unique_ptr<void, decltype(release)> handle(tjInitDecompress(), release);
  if (!handle) throw InputError(file, field, "cannot start the JPEG decoder");
  auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto size = static_cast<unsigned long>(bytes.size());
  int w = 0, h = 0, subsampling = 0, colorspace = 0;
  if (tjDecompressHeader3(handle.get(), data, size, &w, &h, &subsampling, &colorspace) != 0)
    throw InputError(file, field, std::string("cannot read JPEG: ") + tjGetErrorStr2(handle.get()));
  checkTextureSize(uint64_t(std::max(w, 0)), uint64_t(std::max(h, 0)), file, field);
  DecodedImage image{w, h, {}};
  image.rgb.resize(size_t(w) * size_t(h) * 3);
  // Warnings (corrupt or truncated data, which libjpeg would fill with grey) are errors, and a
  // progressive file may not hold more than 500 scans (a decoding-time bomb otherwise).
  if (tjDecompress2(handle.get(), data, size, image.rgb.data(), w, 0, h, TJPF_RGB,
                    TJFLAG_STOPONWARNING | TJFLAG_LIMITSCANS) != 0)
    throw InputError(file, field, std::string("cannot read JPEG: ") + tjGetErrorStr2(handle.get()));
  return image;
}

}  // namespace

DecodedImage decodeTexture(std::string_view bytes, const std::string& file,
                           const std::string& field) {
  const auto starts = [&](std::string_view magic) {
    return bytes.substr(0, magic.size()) == magic;
  };
  if (starts("\x89PNG\r\n\x1a\n")) return decodePng(bytes, file, field);
  if (starts("\xff\xd8\xff")) return decodeJpeg(bytes, file, field);
  throw InputError(file, field, "not a PNG or JPEG image (voxgi reads textures in those two)");
}

DecodedImage readTexture(const std::string& path, const std::string& referrer,
                         const std::string& field) {
  try {
    return decodeTexture(readInputFile(path, "", "texture image"), path, "");
  } catch (const InputError& e) {
    throw InputError(referrer, field, e.what());
  }
}

}  // namespace voxgi
