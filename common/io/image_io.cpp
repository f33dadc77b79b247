#include "common/io/image_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <Iex.h>

// PNG through libpng's simplified API: a maintained decoder that checks its input (stb_image, used
// before, has undefined behaviour on crafted files, which the image_png fuzz target found).
#include <png.h>

#include "common/error.h"
#include "common/io/exr_check.h"
#include "common/io/input_file.h"
#include "common/memory.h"
#include "common/io/output_file.h"

namespace voxgi {

namespace {

// OpenEXR's view of an image's pixels (glm::vec3, row-major) as R, G and B float channels, the
// pixel (0, 0) at `base`.
Imf::FrameBuffer rgbFrameBuffer(char* base, int width) {
  const size_t xs = sizeof(glm::vec3), ys = xs * size_t(width);
  Imf::FrameBuffer fb;
  for (int c = 0; c < 3; ++c)
    fb.insert(c == 0   ? "R"
              : c == 1 ? "G"
                       : "B",
              Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), xs, ys));
  return fb;
}

}  // namespace

void writeExr(const std::string& path, const Image& image) {
  checkOutputPath(path);
  Imf::StdOSStream bytes;  // encoded in memory, then written atomically
  try {
    Imf::Header header(image.width, image.height);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(bytes, header);
    auto* base = reinterpret_cast<char*>(const_cast<glm::vec3*>(image.pixels.data()));
    const Imf::FrameBuffer fb = rgbFrameBuffer(base, image.width);
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot encode EXR: ") + e.what());
  }
  writeFileAtomically(path, bytes.str());
}

Image readExr(const std::string& path) {
  checkExrHeader(path);
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    // checkExrHeader bounded the window to 16384 per side; the channels and the chunks are checked
    // before the pixels are allocated (a missing channel would silently read as zeros).
    const int64_t w = int64_t(dw.max.x) - dw.min.x + 1, h = int64_t(dw.max.y) - dw.min.y + 1;
    for (const char* c : {"R", "G", "B"})
      if (file.header().channels().findChannel(c) == nullptr)
        throw InputError(path, std::string("channel ") + c,
                         "missing: voxgi reads linear RGB (R, G and B channels)");
    // Every chunk of pixels must be in the file's offset table before the image is allocated: a
    // truncated file, or a header that declares a larger window than the file holds, is refused.
    if (!file.isComplete())
      throw InputError(path, "data window",
                       std::to_string(w) + "x" + std::to_string(h) +
                           ": the file does not hold every pixel (truncated or corrupt)");
    requireMemory(uint64_t(w) * uint64_t(h) * sizeof(glm::vec3), "the image", path, "data window");
    Image image{int(w), int(h)};
    const size_t xs = sizeof(glm::vec3), ys = xs * size_t(image.width);
    auto* base = reinterpret_cast<char*>(image.pixels.data()) -
                 (ptrdiff_t(dw.min.x) * ptrdiff_t(xs) + ptrdiff_t(dw.min.y) * ptrdiff_t(ys));
    const Imf::FrameBuffer fb = rgbFrameBuffer(base, image.width);
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot read EXR: ") + e.what());
  }
}

Image readImage(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".png") return readExr(path);
  const uint64_t fileBytes = requireInputFile(path, "", "PNG image");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw InputError(path, "", std::string("cannot read PNG: ") + png.message);
  // The size is checked before the pixels are allocated, as for every other loader.
  if (png.width < 1 || png.height < 1 || png.width > 16384 || png.height > 16384) {
    png_image_free(&png);
    throw InputError(path, "size",
                     std::to_string(png.width) + "x" + std::to_string(png.height) +
                         " is outside 1..16384 per side");
  }
  // Deflate expands at most 1032:1, and a row holds at least a filter byte and one bit per pixel:
  // a header that declares more than the file can hold is refused before anything is allocated.
  const uint64_t leastRawBytes = uint64_t(png.height) * (1 + (uint64_t(png.width) + 7) / 8);
  if (leastRawBytes > 1032 * fileBytes) {
    png_image_free(&png);
    throw InputError(path, "size",
                     std::to_string(png.width) + "x" + std::to_string(png.height) +
                         " cannot be compressed into " + std::to_string(fileBytes) +
                         " bytes (the file is truncated or corrupt)");
  }
  png.format = PNG_FORMAT_RGB;  // 8-bit sRGB whatever the file's colour type and depth
  try {
    requireMemory(uint64_t(png.width) * png.height * (3 + sizeof(glm::vec3)), "the image", path,
                  "size");
  } catch (...) {
    png_image_free(&png);
    throw;
  }
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw InputError(path, "", "cannot read PNG: " + message);
  }
  Image image(int(png.width), int(png.height));
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      image.pixels[i][c] = srgbToLinear(float(bytes[i * 3 + size_t(c)]) / 255.0f);
  return image;
}

void writeRgb8Png(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb) {
  checkOutputPath(path);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(width);
  png.height = png_uint_32(height);
  png.format = PNG_FORMAT_RGB;
  // Encoded in memory (libpng says how much room it needs first), then written atomically.
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, rgb.data(), 0, nullptr))
    throw InputError(path, "", std::string("cannot encode PNG: ") + png.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
    throw InputError(path, "", std::string("cannot encode PNG: ") + png.message);
  bytes.resize(size);
  writeFileAtomically(path, bytes);
}

void writePng(const std::string& path, const Image& image, float exposure) {
  std::vector<unsigned char> bytes(size_t(image.width) * size_t(image.height) * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[i * 3 + size_t(c)] = static_cast<unsigned char>(
          std::lround(255.0f * linearToSrgb(exposure * image.pixels[i][c])));
  writeRgb8Png(path, image.width, image.height, bytes);
}

}  // namespace voxgi
