// The path tracer's samplers (validation/reference/sampler.h): the construction's promises,
// checked point by point.
#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "validation/reference/sampler.h"

namespace voxgi::reference {
namespace {

// Sobol's first dimensions against their definition, in index order (not Gray-code order):
// dimension 0 is the van der Corput sequence (1/2, 1/4, 3/4, 1/8, ...); dimension 1 sums the
// direction numbers 1/2, 3/4, 5/8 (binary 0.1, 0.11, 0.101: Pascal's triangle mod 2) over the
// index's bits.
TEST(PathSampler, SobolsFirstDimensionsAreTheKnownPoints) {
  const double vdc[] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double second[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(sobol::dimension0(i) * 0x1p-32, vdc[i]) << i;
    EXPECT_EQ(sobol::dimension1(i) * 0x1p-32, second[i]) << i;
  }
}

// A scramble is a bijection that keeps aligned blocks: the 2^m values with the same high bits
// map onto the 2^m values of one block.
TEST(PathSampler, OwenScrambleMapsAlignedBlocksOntoAlignedBlocks) {
  for (const uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
    for (const int m : {1, 4, 10}) {
      const uint32_t base = 0x12345678u & ~((1u << m) - 1u);
      std::set<uint32_t> out, highs;
      for (uint32_t k = 0; k < (1u << m); ++k) {
        const uint32_t y = sobol::owenScramble(base + k, seed);
        out.insert(y);
        highs.insert(y >> m);
      }
      EXPECT_EQ(out.size(), size_t(1) << m) << seed << " " << m;
      EXPECT_EQ(highs.size(), 1u) << seed << " " << m;
    }
  }
}

// The first 2^m samples of a pixel, per get2D call, are a (0,m,2)-net: for every split of m
// into a + b, the 2^a x 2^b elementary intervals hold one point each. get1D's are stratified
// into 2^m intervals. Several pixels, seeds and calls (the later calls are padded dimensions).
TEST(PathSampler, SobolPrefixesAreZeroMTwoNets) {
  for (const uint64_t seed : {0ull, 7ull}) {
    for (const uint64_t pixel : {0ull, 1ull, 4097ull}) {
      for (const int m : {0, 1, 2, 5, 8, 12}) {
        const uint32_t n = 1u << m;
        constexpr int kCalls = 4;
        std::vector<std::vector<glm::vec2>> points(kCalls);
        std::vector<std::vector<float>> singles(kCalls);
        for (uint32_t s = 0; s < n; ++s) {
          SobolSampler sampler(seed, pixel, s);
          for (int c = 0; c < kCalls; ++c) {
            points[size_t(c)].push_back(sampler.get2D());
            singles[size_t(c)].push_back(sampler.get1D());
          }
        }
        for (int c = 0; c < kCalls; ++c) {
          for (int a = 0; a <= m; ++a) {
            std::set<std::pair<int, int>> cells;
            for (const glm::vec2 p : points[size_t(c)]) {
              ASSERT_GE(p.x, 0.0f);
              ASSERT_LT(p.x, 1.0f);
              ASSERT_GE(p.y, 0.0f);
              ASSERT_LT(p.y, 1.0f);
              cells.insert({int(p.x * float(1 << a)), int(p.y * float(1 << (m - a)))});
            }
            EXPECT_EQ(cells.size(), n) << "seed " << seed << " pixel " << pixel << " m " << m
                                       << " call " << c << " split " << a;
          }
          std::set<int> strata;
          for (const float u : singles[size_t(c)]) strata.insert(int(u * float(n)));
          EXPECT_EQ(strata.size(), n) << "1D, m " << m << " call " << c;
        }
      }
    }
  }
}

// The numbers are a function of (seed, pixel, sample, call) only, and a change of any of them
// changes the scrambles: two pixels' first points differ.
TEST(PathSampler, NumbersDependOnlyOnSeedPixelSampleAndCall) {
  SobolSampler a(3, 10, 5), b(3, 10, 5), otherPixel(3, 11, 5), otherSeed(4, 10, 5);
  for (int c = 0; c < 6; ++c) {
    const glm::vec2 p = a.get2D(), q = b.get2D();
    EXPECT_EQ(p, q);
    EXPECT_NE(p, otherPixel.get2D());
    EXPECT_NE(p, otherSeed.get2D());
  }
  IndependentSampler i(3, 10, 5), j(3, 10, 5);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(i.get2D(), j.get2D());
}

// Over many pixels, a scrambled sample is uniform: the mean of each call's coordinate over 4096
// pixels (one sample each) is 1/2 within 5 standard errors (sqrt(1/12 / 4096) = 0.0045).
TEST(PathSampler, ScrambledPointsAreUniformAcrossPixels) {
  for (int c = 0; c < 4; ++c) {
    double sx = 0.0, sy = 0.0;
    for (uint64_t pixel = 0; pixel < 4096; ++pixel) {
      SobolSampler s(0, pixel, 0);
      for (int k = 0; k < c; ++k) s.get2D();
      const glm::vec2 p = s.get2D();
      sx += p.x;
      sy += p.y;
    }
    EXPECT_NEAR(sx / 4096.0, 0.5, 0.0225) << c;
    EXPECT_NEAR(sy / 4096.0, 0.5, 0.0225) << c;
  }
}

}  // namespace
}  // namespace voxgi::reference
