#include <filesystem>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "tests/test_scenes.h"

namespace voxgi {
namespace {

TEST(ImageIo, ExrRoundTripIsExact) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = {float(x) * 0.1f, float(y) * 1e3f, -1.5e-7f};
  const std::string path = test::testTempDir() + "img.exr";
  writeExr(path, image);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const Image back = readExr(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST(ImageIo, SrgbCurveAndPng) {
  EXPECT_FLOAT_EQ(linearToSrgb(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(linearToSrgb(1.0f), 1.0f);
  EXPECT_NEAR(linearToSrgb(0.18f), 0.4614f, 1e-4);  // middle grey
  EXPECT_FLOAT_EQ(linearToSrgb(7.0f), 1.0f);
  const std::string path = test::testTempDir() + "img.png";
  writePng(path, Image(4, 4));
  EXPECT_GT(std::filesystem::file_size(path), 0u);
  EXPECT_THROW(readExr(path), InputError);
}

}  // namespace
}  // namespace voxgi
