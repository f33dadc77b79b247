// trace_cones' diffuse cones at a reduced resolution (cones.diffuse_scale), checked against the
// image that traces every pixel's cones: each pixel is its own full-resolution value or a mean of
// the full-resolution values at the samples of the blocks around it, and the depth- and
// normal-aware weights put the light where the nearest sample does not.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "common/settings.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr int kImage = 50;  // not a multiple of 3 or 4: the last blocks are partial

Scene cornellBox() {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 32;
  scene.camera.width = scene.camera.height = kImage;
  return scene;
}

struct Traced {
  Buffer indirect;  // vct/trace_cones.indirect_diffuse
  Buffer ids;       // gbuffer.object_id
};

Traced trace(const Scene& scene, int scale) {
  Settings settings = resolveSettings(vct(), scene.settings, scene.file, "default",
                                      {"cones.diffuse_scale=" + std::to_string(scale)});
  BufferSet b = runCpuUntil(scene, settings, "trace_cones");
  return {b.take(BufferId::vct_trace_cones_indirect_diffuse),
          b.take(BufferId::common_gbuffer_object_id)};
}

bool surface(const Traced& t, int x, int y) {
  return t.ids.get<uint32_t>(size_t(y) * kImage + size_t(x), 0) != 0u;
}

// The sample pixel of block (bx, by), as docs/stages/vct/trace_cones.md states the rule: the
// block's centre pixel (scale / 2 along each axis) if it has a surface, else the next pixel of the
// block with one in scan order from there, wrapping; -1 when the block has none or lies outside.
glm::ivec2 samplePixel(const Traced& t, int bx, int by, int scale) {
  const int blocks = (kImage + scale - 1) / scale;
  if (bx < 0 || by < 0 || bx >= blocks || by >= blocks) return glm::ivec2(-1);
  const int centre = scale / 2;
  for (int k = 0; k < scale * scale; ++k) {
    const int i = (centre * scale + centre + k) % (scale * scale);
    const int x = bx * scale + i % scale, y = by * scale + i / scale;
    if (x < kImage && y < kImage && surface(t, x, y)) return {x, y};
  }
  return glm::ivec2(-1);
}

// The blocks whose samples a pixel may blend: the 2 x 2 whose centres surround its centre.
glm::ivec2 firstBlock(int x, int y, int scale) {
  return {int(std::floor((x + 0.5) / scale - 0.5)), int(std::floor((y + 0.5) / scale - 0.5))};
}

// Every pixel holds its own full-resolution value (it traced its own cones) or a value within
// the range, per channel, of the full-resolution values at its blocks' sample pixels; and some
// of each (the box has edges and flat walls).
TEST(DiffuseUpsample, EachPixelIsItsOwnOrAMeanOfItsBlocksSamples) {
  const Scene scene = cornellBox();
  const Traced full = trace(scene, 1);
  for (const int scale : {2, 3, 4}) {
    const Traced up = trace(scene, scale);
    int own = 0, blended = 0;
    for (int y = 0; y < kImage; ++y)
      for (int x = 0; x < kImage; ++x) {
        const size_t e = size_t(y) * kImage + size_t(x);
        if (!surface(full, x, y)) {
          EXPECT_EQ(up.indirect.vec3At(e), glm::vec3(0.0f));
          continue;
        }
        if (up.indirect.vec3At(e) == full.indirect.vec3At(e)) {
          ++own;
          continue;
        }
        ++blended;
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        const glm::ivec2 first = firstBlock(x, y, scale);
        for (int k = 0; k < 4; ++k) {
          const glm::ivec2 s = samplePixel(full, first.x + (k & 1), first.y + (k >> 1), scale);
          if (s.x < 0) continue;
          const glm::vec3 v = full.indirect.vec3At(size_t(s.y) * kImage + size_t(s.x));
          lo = glm::min(lo, v);
          hi = glm::max(hi, v);
        }
        const glm::vec3 got = up.indirect.vec3At(e);
        for (int c = 0; c < 3; ++c) {
          // A weighted mean rounds within a few ulps of its range.
          const float slack = 1e-6f * std::max(std::abs(lo[c]), std::abs(hi[c]));
          ASSERT_GE(got[c], lo[c] - slack) << "scale " << scale << " pixel " << x << "," << y;
          ASSERT_LE(got[c], hi[c] + slack) << "scale " << scale << " pixel " << x << "," << y;
        }
      }
    std::printf("scale %d: %d pixels traced their own cones, %d blended\n", scale, own, blended);
    EXPECT_GT(own, 0) << scale;
    EXPECT_GT(blended, own) << scale;
  }
}

// The upsampled light's error against the full-resolution image, beside two upsamplings that
// know nothing of the surfaces: the nearest sample (each pixel takes its own block's) and the
// samples' bilinear blend. The depth and normal weights keep one surface's light off another, so
// the blend errs less than either.
TEST(DiffuseUpsample, DepthAndNormalWeightsBeatNearestAndBilinear) {
  const Scene scene = cornellBox();
  const Traced full = trace(scene, 1);
  const auto at = [&](glm::ivec2 p) {
    return glm::dvec3(full.indirect.vec3At(size_t(p.y) * kImage + size_t(p.x)));
  };
  for (const int scale : {2, 4}) {
    const Traced up = trace(scene, scale);
    double blendError = 0.0, nearestError = 0.0, bilinearError = 0.0, energy = 0.0;
    const auto add = [](double& sum, glm::dvec3 got, glm::dvec3 want) {
      const glm::dvec3 d = got - want;
      sum += glm::dot(d, d);
    };
    for (int y = 0; y < kImage; ++y)
      for (int x = 0; x < kImage; ++x) {
        if (!surface(full, x, y)) continue;
        const glm::dvec3 want = at({x, y});
        const glm::ivec2 own = samplePixel(full, x / scale, y / scale, scale);
        ASSERT_GE(own.x, 0);  // the pixel's own block has a surface: this pixel's
        const glm::dvec2 t((x + 0.5) / scale - 0.5, (y + 0.5) / scale - 0.5);
        const glm::ivec2 first = firstBlock(x, y, scale);
        const glm::dvec2 f = t - glm::floor(t);
        glm::dvec3 bilinear(0.0);
        double weights = 0.0;
        for (int k = 0; k < 4; ++k) {
          const int dx = k & 1, dy = k >> 1;
          const glm::ivec2 s = samplePixel(full, first.x + dx, first.y + dy, scale);
          if (s.x < 0) continue;
          const double w = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y);
          bilinear += w * at(s);
          weights += w;
        }
        add(blendError, glm::dvec3(up.indirect.vec3At(size_t(y) * kImage + size_t(x))), want);
        add(nearestError, at(own), want);
        add(bilinearError, bilinear / weights, want);
        energy += glm::dot(want, want);
      }
    std::printf(
        "scale %d: relative squared error %.5f upsampled, %.5f nearest sample, %.5f "
        "bilinear\n",
        scale, blendError / energy, nearestError / energy, bilinearError / energy);
    EXPECT_LT(blendError, nearestError) << scale;
    EXPECT_LT(blendError, bilinearError) << scale;
  }
}

}  // namespace
}  // namespace voxgi::test
