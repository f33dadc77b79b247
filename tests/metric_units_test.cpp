// The metrics of docs/accuracy.md do not depend on the scene's units: the Cornell box with every
// emitter and light 1000 x brighter (the same scene in other units of radiance) renders 1000 x
// brighter with both vct and the path tracer, and every relative metric, SSIM and the energy
// ratio measure the same. The absolute form (--units absolute), measured beside it, does not:
// that is what the default fixes.
#include <gtest/gtest.h>

#include "common/io/buffer_io.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/path_trace.h"

namespace voxgi::test {
namespace {

using reference::MetricUnits;

Scene box(float brightness) {
  Scene s = loadScene(sourcePath("scenes/cornell_box.json"));
  s.grid.resolution = 16;
  setImageWidth(s, 32, "test");
  for (Material& m : s.materials) m.emission *= brightness;
  Light point;  // a point light too, so lights scale as well as emitters
  point.position = {278.0, 400.0, 280.0};
  point.intensity = glm::vec3(2e4f * brightness);
  s.lights.push_back(point);
  return s;
}

struct Measured {
  reference::ImageMetrics mean, absolute;
};

Measured measure(float brightness) {
  const Scene scene = box(brightness);
  reference::PathTraceOptions o;
  o.spp = 64;
  o.bounces = 1;
  const Image ref = reference::pathTrace(scene, o).image;
  const Image vct =
      bufferImage(runCpuUntil(scene, Settings{}, "compose").at(BufferId::vct_compose_color));
  return {reference::compareImages(vct, ref, {}, MetricUnits::reference_mean),
          reference::compareImages(vct, ref, {}, MetricUnits::absolute)};
}

TEST(MetricUnits, A1000TimesBrighterSceneMeasuresTheSame) {
  const Measured dim = measure(1.0f), bright = measure(1000.0f);
  const auto same = [](double a, double b) { return std::abs(a / b - 1.0) < 1e-4; };
  EXPECT_GT(dim.mean.relMse, 0.0);
  EXPECT_TRUE(same(bright.mean.relMse, dim.mean.relMse))
      << bright.mean.relMse << " " << dim.mean.relMse;
  EXPECT_TRUE(same(bright.mean.mare, dim.mean.mare)) << bright.mean.mare << " " << dim.mean.mare;
  EXPECT_NEAR(bright.mean.ssim, dim.mean.ssim, 1e-4);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(bright.mean.energy[c], dim.mean.energy[c], 1e-4);
  EXPECT_NEAR(bright.mean.rmse / dim.mean.rmse, 1000.0, 0.1);  // RMSE keeps the images' units
  // In absolute units the dark box's epsilon dominates, the bright one's does not.
  EXPECT_GT(bright.absolute.relMse, 3.0 * dim.absolute.relMse);
}

}  // namespace
}  // namespace voxgi::test
