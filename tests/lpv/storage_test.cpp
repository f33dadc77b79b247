// lpv.storage=f16 (T16 of docs/lpv.md): the rounding to half precision is the IEEE one (checked
// against the compiler's _Float16), and propagation in half precision stays within 2^-10 per step
// of f32.
#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "common/scene_io/scene_load.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/lpv/storage.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

float viaCompiler(float x) {
  return static_cast<float>(static_cast<_Float16>(x));
}

TEST(HalfFloat, RoundsAsIeeeBinary16) {
  const float inf = std::numeric_limits<float>::infinity();
  for (float x : {0.0f, -0.0f, 1.0f, 65504.0f, 65519.99f, 65520.0f, -65520.0f, 1e-8f,
                  std::ldexp(1.0f, -24), std::ldexp(3.0f, -25), std::ldexp(1.0f, -25),
                  std::ldexp(1.0f, -14), std::ldexp(1.0f, -14) - std::ldexp(1.0f, -30),
                  1.0f + std::ldexp(1.0f, -11), 1.0f + std::ldexp(3.0f, -11), inf, -inf, 1e30f})
    EXPECT_EQ(std::bit_cast<uint32_t>(shared::roundToHalf(x)),
              std::bit_cast<uint32_t>(viaCompiler(x)))
        << x;
  EXPECT_TRUE(std::isnan(shared::roundToHalf(std::numeric_limits<float>::quiet_NaN())));
  std::mt19937 random(7);
  std::uniform_int_distribution<uint32_t> bits(0u, 0x7f7fffffu);  // every finite magnitude
  for (int i = 0; i < 200000; ++i) {
    const float x = std::bit_cast<float>(bits(random) | (i % 2 == 0 ? 0u : 0x80000000u));
    ASSERT_EQ(std::bit_cast<uint32_t>(shared::roundToHalf(x)),
              std::bit_cast<uint32_t>(viaCompiler(x)))
        << x;
  }
}

// The GPU's packing (halfBits, halfValue) is exact both ways on every half: the value of each
// 16-bit pattern is the compiler's, and packing it gives the pattern back (NaNs stay NaNs).
TEST(HalfFloat, BitsAndValuesRoundTripOnEveryHalf) {
  for (uint32_t h = 0; h <= 0xffffu; ++h) {
    const float v = shared::halfValue(h);
    const float expected = static_cast<float>(std::bit_cast<_Float16>(uint16_t(h)));
    if (std::isnan(expected)) {
      ASSERT_TRUE(std::isnan(v)) << h;
      ASSERT_TRUE(std::isnan(shared::halfValue(shared::halfBits(v)))) << h;
      continue;
    }
    ASSERT_EQ(std::bit_cast<uint32_t>(v), std::bit_cast<uint32_t>(expected)) << h;
    ASSERT_EQ(shared::halfBits(v), h) << h;
  }
}

// lpv.storage=f16's packed volumes (common/lpv/propagate.h): 27 stored values a cell (HOLPV)
// take 14 words, and unpacking gives every stored value back bit for bit, subnormal halves and
// negative zeros included.
TEST(LpvStorage, PackedVolumesHoldEveryStoredValueExactly) {
  shared::PropagateParams params{};
  params.halfPrecision = 1;
  params.storageScale = 8.0f;
  params.inverseStorageScale = 0.125f;
  constexpr int kValues = 27;
  constexpr size_t kCells = 1000;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> exponent(-30.0f, 3.0f);
  std::vector<float> volume(kCells * kValues);
  for (size_t i = 0; i < volume.size(); ++i) {
    const float x = std::exp2(exponent(random)) * (i % 3 == 0 ? -1.0f : 1.0f);
    volume[i] = i % 97 == 0 ? -0.0f : shared::storedValue(x, params);
  }
  const std::vector<uint32_t> packed = lpv::packStoredVolume(volume, kValues, params);
  ASSERT_EQ(packed.size(), kCells * 14);
  std::vector<uint32_t> back(volume.size());
  lpv::unpackStoredVolume(packed.data(), kCells, kValues, params, back.data());
  size_t subnormal = 0;
  for (size_t i = 0; i < volume.size(); ++i) {
    ASSERT_EQ(back[i], std::bit_cast<uint32_t>(volume[i])) << i;
    subnormal += volume[i] != 0.0f && std::abs(volume[i]) * 0.125f < std::ldexp(1.0f, -14);
  }
  EXPECT_GT(subnormal, 100u);
}

// Each step's half-precision volume against the f32 one, relative to the step's largest value:
// within 2^-10 (k + 1) at step k (T16's bound; measured 2.5e-4 .. 5.2e-4 over steps 0 .. 8), and
// not identical (the setting rounds).
TEST(LpvStorage, HalfPrecisionStaysWithinItsBoundPerStep) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box_lpv.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 16;
  const Technique& holpv = findTechnique("holpv");
  Settings settings = resolveSettings(holpv, scene.settings, scene.file, "default",
                                      {"propagate.steps=8", "propagate.history=on"});
  const lpv::ShBuffers sh = lpv::shBuffers(settings.lpv);
  const BufferSet full = runCpuUntil(holpv, scene, settings, "propagate");
  settings.lpv.storage = LpvStorage::f16;
  const BufferSet half = runCpuUntil(holpv, scene, settings, "propagate");
  const Buffer &a = full.at(sh.steps), &b = half.at(sh.steps);
  const size_t perStep = 16u * 16u * 16u * 27u;
  for (int k = 0; k <= 8; ++k) {
    double largest = 0.0, worst = 0.0;
    for (size_t w = size_t(k) * perStep; w < size_t(k + 1) * perStep; ++w) {
      const float x = std::bit_cast<float>(a.words[w]), y = std::bit_cast<float>(b.words[w]);
      largest = std::max(largest, double(std::abs(x)));
      worst = std::max(worst, double(std::abs(x - y)));
    }
    EXPECT_GT(worst, 0.0) << "step " << k;
    EXPECT_LE(worst, std::ldexp(double(k + 1), -10) * largest) << "step " << k;
  }
}

}  // namespace
}  // namespace voxgi::test
