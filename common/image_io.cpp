#include "common/image_io.h"

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

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "common/error.h"
#include "common/input_file.h"
#include "common/output_file.h"

namespace voxgi {

float linearToSrgb(float linear) {
  const float x = std::clamp(linear, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  const float x = std::clamp(encoded, 0.0f, 1.0f);
  return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

void writeExr(const std::string& path, const Image& image) {
  checkOutputPath(path);
  Imf::StdOSStream bytes;  // encoded in memory, then written atomically
  try {
    Imf::Header header(image.width, image.height);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(bytes, header);
    Imf::FrameBuffer fb;
    auto* base = reinterpret_cast<char*>(const_cast<glm::vec3*>(image.pixels.data()));
    const size_t xs = sizeof(glm::vec3), ys = xs * size_t(image.width);
    for (int c = 0; c < 3; ++c)
      fb.insert(c == 0   ? "R"
                : c == 1 ? "G"
                         : "B",
                Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), xs, ys));
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot encode EXR: ") + e.what());
  }
  writeFileAtomically(path, bytes.str());
}

Image readExr(const std::string& path) {
  requireInputFile(path, "", "EXR image");
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    Image image(dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1);
    Imf::FrameBuffer fb;
    const size_t xs = sizeof(glm::vec3), ys = xs * size_t(image.width);
    auto* base = reinterpret_cast<char*>(image.pixels.data()) -
                 (ptrdiff_t(dw.min.x) * ptrdiff_t(xs) + ptrdiff_t(dw.min.y) * ptrdiff_t(ys));
    for (int c = 0; c < 3; ++c)
      fb.insert(c == 0   ? "R"
                : c == 1 ? "G"
                         : "B",
                Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), xs, ys));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot read EXR: ") + e.what());
  }
}

Image readImage(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".png") return readExr(path);
  requireInputFile(path, "", "PNG image");
  int w = 0, h = 0, channels = 0;
  unsigned char* bytes = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (bytes == nullptr)
    throw InputError(path, "", std::string("cannot read PNG: ") + stbi_failure_reason());
  Image image(w, h);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      image.pixels[i][c] = srgbToLinear(float(bytes[i * 3 + size_t(c)]) / 255.0f);
  stbi_image_free(bytes);
  return image;
}

void writeRgb8Png(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb) {
  checkOutputPath(path);
  std::string bytes;  // encoded in memory, then written atomically
  const auto append = [](void* out, void* data, int size) {
    static_cast<std::string*>(out)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, 3, rgb.data(), width * 3))
    throw InputError(path, "", "cannot encode PNG");
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
