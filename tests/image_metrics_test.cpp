// The image metrics of `voxgi compare` (validation/reference/image_metrics.h) on small synthetic
// images with answers worked out by hand, and the Pareto front of `voxgi study`.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "validation/reference/image_metrics.h"
#include "validation/reference/pareto.h"
#include "validation/reference/temporal_metrics.h"

namespace voxgi::test {
namespace {

using reference::compareImages;
using reference::kRelativeEpsilon;
using reference::MetricUnits;
constexpr MetricUnits kAbsolute = MetricUnits::absolute;

Image constant(int w, int h, glm::vec3 value) {
  Image image(w, h);
  for (glm::vec3& p : image.pixels) p = value;
  return image;
}

// Noise in [0.2, 0.8] per channel: a textured image for SSIM.
Image texture(int w, int h, unsigned seed) {
  Image image(w, h);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(0.2f, 0.8f);
  for (glm::vec3& p : image.pixels) p = glm::vec3(u(random), u(random), u(random));
  return image;
}

// The sRGB curve written out here rather than taken from the code under test.
double srgb(double x) {
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
  const Image a = texture(24, 16, 1);
  const auto m = compareImages(a, a);
  EXPECT_EQ(m.pixels, 24u * 16u);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.relMse, 0.0);
  EXPECT_EQ(m.mare, 0.0);
  EXPECT_NEAR(m.ssim, 1.0, 1e-9);
}

TEST(ImageMetrics, ConstantOffsetGivesTheClosedForms) {
  // Test 1.1 against reference 1 in every channel, and 0.3 against 0.1, in absolute units.
  const auto m = compareImages(constant(16, 16, glm::vec3(1.1f)), constant(16, 16, glm::vec3(1.0f)),
                               {}, kAbsolute);
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(m.relMse, 0.01 / (1.0 + kRelativeEpsilon), 1e-6);
  EXPECT_NEAR(m.mare, 0.1 / (1.0 + kRelativeEpsilon), 1e-6);
  EXPECT_NEAR(m.energy.g, 1.1, 1e-6);
  const auto dark = compareImages(constant(16, 16, glm::vec3(0.3f)),
                                  constant(16, 16, glm::vec3(0.1f)), {}, kAbsolute);
  EXPECT_NEAR(dark.rmse, 0.2, 1e-6);
  EXPECT_NEAR(dark.relMse, 0.04 / (0.01 + kRelativeEpsilon), 1e-5);
  EXPECT_NEAR(dark.mare, 0.2 / (0.1 + kRelativeEpsilon), 1e-5);
  // In units of the reference's mean (0.1): eps is 0.01 x 0.1^2 and 0.01 x 0.1.
  const auto unitFree =
      compareImages(constant(16, 16, glm::vec3(0.3f)), constant(16, 16, glm::vec3(0.1f)));
  EXPECT_NEAR(unitFree.relMse, 0.04 / (0.01 + kRelativeEpsilon * 0.01), 1e-4);
  EXPECT_NEAR(unitFree.mare, 0.2 / (0.1 + kRelativeEpsilon * 0.1), 1e-5);
  EXPECT_NEAR(unitFree.energy.r, 3.0, 1e-5);
}

TEST(ImageMetrics, SsimOfConstantImagesIsTheLuminanceTerm) {
  // No variance: SSIM = (2 x y + C1) / (x^2 + y^2 + C1) of the display values.
  const double x = srgb(0.2), y = srgb(0.4), c1 = 1e-4;
  const auto m = compareImages(constant(16, 16, glm::vec3(0.2f)), constant(16, 16, glm::vec3(0.4f)),
                               {}, kAbsolute);
  EXPECT_NEAR(m.ssim, (2 * x * y + c1) / (x * x + y * y + c1), 1e-6);
  // In the reference's units the display puts its mean (0.4) at middle grey: 0.18 and 0.09.
  const double xm = srgb(0.09), ym = srgb(0.18);
  const auto mean =
      compareImages(constant(16, 16, glm::vec3(0.2f)), constant(16, 16, glm::vec3(0.4f)));
  EXPECT_NEAR(mean.ssim, (2 * xm * ym + c1) / (xm * xm + ym * ym + c1), 1e-6);
}

// The same two images in other units (x 1000, as a scene whose lights and emitters are all
// 1000 x brighter renders): every relative metric, SSIM and the energy stay; in absolute units
// they do not, which is what the default fixes.
TEST(ImageMetrics, RelativeMetricsDoNotDependOnTheImagesUnits) {
  Image reference = texture(32, 24, 4), test = texture(32, 24, 5);
  for (size_t e = 0; e < reference.pixels.size(); e += 7) reference.pixels[e] = glm::vec3(0.0f);
  for (glm::vec3& p : reference.pixels) p *= glm::vec3(0.05f, 0.04f, 0.02f);  // a dim, warm scene
  for (glm::vec3& p : test.pixels) p *= 0.04f;
  Image bigReference = reference, bigTest = test;
  for (glm::vec3& p : bigReference.pixels) p *= 1000.0f;
  for (glm::vec3& p : bigTest.pixels) p *= 1000.0f;
  for (const MetricUnits units : {MetricUnits::reference_mean, kAbsolute}) {
    const auto small = compareImages(test, reference, {}, units);
    const auto big = compareImages(bigTest, bigReference, {}, units);
    const bool invariant = units == MetricUnits::reference_mean;
    EXPECT_EQ(std::abs(big.relMse / small.relMse - 1.0) < 1e-5, invariant) << big.relMse;
    EXPECT_EQ(std::abs(big.mare / small.mare - 1.0) < 1e-5, invariant) << big.mare;
    EXPECT_EQ(std::abs(big.ssim - small.ssim) < 1e-5, invariant) << big.ssim << " " << small.ssim;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(big.energy[c], small.energy[c], 1e-5);
    EXPECT_NEAR(big.rmse / small.rmse, 1000.0, 1e-2);  // RMSE is in the images' units
  }
}

// Black scores mean r^2 / (r^2 + eps u^2) and energy 0; the reference's mean scores energy 1.
TEST(ImageMetrics, BaselinesScoreTheirClosedForms) {
  Image reference = constant(8, 8, glm::vec3(0.0f));
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 4; ++y) reference.at(x, y) = glm::vec3(2.0f);  // half 2, half 0: mean 1
  const auto scale = reference::metricScale(reference, {}, MetricUnits::reference_mean);
  EXPECT_EQ(scale.unit, glm::dvec3(1.0));
  const reference::Baselines b = reference::trivialBaselines(reference, {}, scale);
  EXPECT_NEAR(b.black.relMse, 0.5 * 4.0 / (4.0 + kRelativeEpsilon), 1e-9);
  EXPECT_EQ(b.black.energy, glm::dvec3(0.0));
  // The constant 1: error 1 everywhere, over 4 + eps and over eps.
  EXPECT_NEAR(b.constant.relMse, 0.5 / (4.0 + kRelativeEpsilon) + 0.5 / kRelativeEpsilon, 1e-9);
  EXPECT_NEAR(b.constant.energy.g, 1.0, 1e-9);
  EXPECT_LT(b.black.relMse, b.constant.relMse);  // on relMSE, black is the harder baseline here
}

// A black channel is measured in the mean of the others' units; a black reference leaves the
// relative metrics undefined (NaN), never infinite.
TEST(ImageMetrics, BlackChannelsAndBlackReferences) {
  const Image red = constant(8, 8, glm::vec3(0.6f, 0.0f, 0.0f));
  const auto scale = reference::metricScale(red, {}, MetricUnits::reference_mean);
  EXPECT_NEAR(scale.unit.b, 0.2, 1e-7);
  const auto m = compareImages(constant(8, 8, glm::vec3(0.6f, 0.0f, 0.02f)), red);
  EXPECT_TRUE(std::isfinite(m.relMse));
  EXPECT_NEAR(m.relMse, 0.0004 / (kRelativeEpsilon * 0.04) / 3.0, 1e-5);
  EXPECT_TRUE(std::isnan(m.energy.b));
  const Image black = constant(8, 8, glm::vec3(0.0f));
  const auto undefined = compareImages(red, black);
  EXPECT_TRUE(std::isnan(undefined.relMse));
  EXPECT_TRUE(std::isnan(undefined.mare));
  EXPECT_NEAR(undefined.rmse, std::sqrt(0.36 / 3.0), 1e-6);
}

TEST(ImageMetrics, SsimFallsAsNoiseGrowsAndIgnoresChannelsItDoesNotSee) {
  const Image reference = texture(32, 32, 2);
  double previous = 1.0;
  for (const float amplitude : {0.01f, 0.05f, 0.2f}) {
    Image noisy = reference;
    std::mt19937 random(3);
    std::uniform_real_distribution<float> u(-amplitude, amplitude);
    for (glm::vec3& p : noisy.pixels) p += glm::vec3(u(random));
    const double ssim = compareImages(noisy, reference).ssim;
    EXPECT_LT(ssim, previous) << amplitude;
    previous = ssim;
  }
  EXPECT_LT(previous, 0.8);
  // Values above 1 clamp on the display, so SSIM does not see them; RMSE does.
  const auto bright = compareImages(constant(16, 16, glm::vec3(2.0f)),
                                    constant(16, 16, glm::vec3(3.0f)), {}, kAbsolute);
  EXPECT_NEAR(bright.ssim, 1.0, 1e-9);
  EXPECT_NEAR(bright.rmse, 1.0, 1e-6);
}

TEST(ImageMetrics, MaskKeepsOnlyItsPixels) {
  Image test = constant(8, 8, glm::vec3(0.5f));
  const Image reference = test;
  std::vector<uint8_t> mask(64, 1);
  for (int x = 0; x < 8; ++x) {
    test.at(x, 0) = glm::vec3(5.0f);  // a bad first row, masked out
    mask[size_t(x)] = 0;
  }
  test.at(3, 4) = glm::vec3(0.6f);  // one kept pixel off by 0.1
  const auto m = compareImages(test, reference, mask);
  EXPECT_EQ(m.pixels, 56u);
  EXPECT_NEAR(m.rmse, std::sqrt(0.01 / 56.0), 1e-6);
  const auto colours = reference::errorColours(
      test, reference, mask, reference::metricScale(reference, mask, MetricUnits::reference_mean));
  EXPECT_EQ(colours[0], 128);                // masked: grey
  EXPECT_EQ(colours[3 * (8 + 0)], 0);        // exact: black
  EXPECT_GT(colours[3 * (4 * 8 + 3)], 100);  // relative error 0.1 / 0.51: yellow
}

TEST(Pareto, KeepsThePointsNothingBeatsInTimeAndError) {
  // (1, 5) fast; (2, 3); (2, 4) beaten by (2, 3); (3, 3) beaten by (2, 3); (4, 1) accurate;
  // (4, 1) again: equal points both stay.
  const std::vector<double> seconds{1, 2, 2, 3, 4, 4}, error{5, 3, 4, 3, 1, 1};
  EXPECT_EQ(reference::paretoFront(seconds, error),
            (std::vector<bool>{true, true, false, false, true, true}));
}

// Flicker (validation/reference/temporal_metrics.h) by hand on two pixels, unit 2 per channel: the
// test jumps by 1 at the first pixel and holds the second, the reference rises by 0.5 at both.
// Changes differ by 0.5 everywhere: error sqrt(0.25 / 4) = 0.25; the reference's own change 0.5
// / 2 = 0.25 (held); variances 0.01 and 0.03 give sqrt(0.04 / 4) = 0.1. A test that follows the
// reference's change exactly, offset by a constant, has no flicker.
TEST(TemporalMetrics, ChangesAgainstTheReferencesByHand) {
  Image testA(2, 1), testB(2, 1), refA(2, 1), refB(2, 1), varA(2, 1), varB(2, 1);
  testB.pixels[0] = glm::vec3(1.0f);
  refB.pixels = {glm::vec3(0.5f), glm::vec3(0.5f)};
  varA.pixels = {glm::vec3(0.01f), glm::vec3(0.01f)};
  varB.pixels = {glm::vec3(0.03f), glm::vec3(0.03f)};
  reference::MetricScale scale;
  scale.unit = glm::dvec3(2.0);
  const reference::TemporalMetrics t =
      reference::compareChanges(testA, testB, refA, refB, {}, scale, varA, varB);
  EXPECT_NEAR(t.error, 0.25, 1e-12);
  EXPECT_NEAR(t.held, 0.25, 1e-12);
  EXPECT_NEAR(t.noise, 0.1, 1e-7);
  EXPECT_TRUE(std::isnan(reference::compareChanges(testA, testB, refA, refB, {}, scale).noise));
  Image offsetA = refA, offsetB = refB;
  for (auto* image : {&offsetA, &offsetB})
    for (glm::vec3& p : image->pixels) p += 3.0f;
  EXPECT_EQ(reference::compareChanges(offsetA, offsetB, refA, refB, {}, scale).error, 0.0);
  // A mask counts its pixels alone. The first pixel jumping by 2 instead (its change 1.5 off the
  // reference's, the second's 0.5 off): sqrt((0.75^2 + 0.25^2) / 2) over both pixels, and the
  // second's 0.5 / 2 alone under a mask that keeps it; a mask ignored would give the first figure.
  Image jumpB = testB;
  jumpB.pixels[0] = glm::vec3(2.0f);
  EXPECT_NEAR(reference::compareChanges(testA, jumpB, refA, refB, {}, scale).error,
              std::sqrt(0.3125), 1e-12);
  EXPECT_NEAR(reference::compareChanges(testA, jumpB, refA, refB, {0, 1}, scale).error, 0.25,
              1e-12);
}

}  // namespace
}  // namespace voxgi::test
