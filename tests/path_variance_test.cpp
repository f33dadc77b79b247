// The path tracer's variance image predicts its actual error (docs/path-tracer.md, "Variance"):
// per pixel and channel, z = (image - converged) / sqrt(its variance + the converged render's)
// has a standard deviation in [0.8, 1.25] for both samplers from 16 to 1024 spp. The renders are
// deterministic (fixed seeds), so the figures below are the test's own every time; one sequence
// with the sample variance (replicas = 1), right for independent samples only, overstates the
// scrambled points' error and fails, which shows the test tells them apart.
#include <cmath>

#include <gtest/gtest.h>

#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"
#include "validation/reference/path_trace.h"

namespace voxgi::test {
namespace {

using reference::PathTraceOptions;
using reference::PathTraceResult;
using reference::SamplerKind;

// The standard deviation of z over the values whose variance is not zero (the emitter seen
// directly has none).
double zSpread(const PathTraceResult& test, const PathTraceResult& converged) {
  double sum = 0.0, square = 0.0;
  size_t count = 0;
  for (size_t e = 0; e < test.image.pixels.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      const double v = double(test.variance.pixels[e][c]) + double(converged.variance.pixels[e][c]);
      if (!(v > 0.0)) continue;
      const double z =
          (double(test.image.pixels[e][c]) - double(converged.image.pixels[e][c])) / std::sqrt(v);
      sum += z;
      square += z * z;
      ++count;
    }
  const double mean = sum / double(count);
  return std::sqrt(square / double(count) - mean * mean);
}

// The Cornell box at 32^2, one bounce: direct light, an area light's edges, soft shadows and a
// bounce, so both smooth and discontinuous pixels.
PathTraceResult render(SamplerKind sampler, int spp, int replicas, uint64_t seed) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  setImageWidth(scene, 32, "test");
  PathTraceOptions o;
  o.spp = spp;
  o.bounces = 1;
  o.sampler = sampler;
  o.replicas = replicas;
  o.seed = seed;
  return reference::pathTrace(scene, o);
}

TEST(PathVariance, PredictsTheErrorOfBothSamplers) {
  // 4096 spp with the default estimator: its own variance (about a quarter of the 1024-spp
  // render's) goes into z's denominator.
  const PathTraceResult converged = render(SamplerKind::sobol, 4096, 2, 0x5eed);
  const PathTraceOptions defaults;
  for (const SamplerKind sampler : {SamplerKind::sobol, SamplerKind::independent})
    for (const int spp : {16, 64, 256, 1024}) {
      const double spread = zSpread(render(sampler, spp, defaults.replicas, 1), converged);
      // Measured 0.94, 0.99, 1.02, 1.00 (sobol) and 0.94, 0.91, 0.92, 0.94 (independent).
      EXPECT_GE(spread, 0.8) << "sampler " << int(sampler) << " spp " << spp;
      EXPECT_LE(spread, 1.25) << "sampler " << int(sampler) << " spp " << spp;
    }
  // One scrambled sequence measured by its sample variance: 0.50 at 256 spp and at 1024.
  for (const int spp : {256, 1024})
    EXPECT_LT(zSpread(render(SamplerKind::sobol, spp, 1, 1), converged), 0.8) << spp;
}

}  // namespace
}  // namespace voxgi::test
