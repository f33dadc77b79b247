// A scene renders the same wherever it sits: the Cornell box moved 1e6, 1e9 and 1e12 units from
// the origin gives the image it gives at the origin, for cone tracing (voxel-local coordinates in
// double) and for the path tracer (coordinates relative to the scene's centre, in double).
#include <gtest/gtest.h>

#include "common/io/buffer_io.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/path_trace.h"

namespace voxgi::test {
namespace {

Scene cornellAt(double offset) {
  Scene s = loadScene(sourcePath("scenes/cornell_box.json"));
  s.grid.resolution = 16;
  s.camera.width = s.camera.height = 32;
  const glm::dvec3 d(offset, -offset, offset);
  for (Mesh& m : s.meshes)
    for (glm::dvec3& p : m.positions) p += d;
  s.camera.position += d;
  s.camera.lookAt += d;
  for (Light& l : s.lights) l.position += d;
  s.grid.min += d;
  return s;
}

double relMse(const Image& test, const Image& reference) {
  return reference::compareImages(test, reference, {}).relMse;
}

TEST(FarFromOrigin, ConeTracingIsTheSameAtAnyOffset) {
  Settings settings;  // the box's own bounce.count=1 is left out: the point is the geometry
  const Image atOrigin =
      bufferImage(runCpuUntil(cornellAt(0.0), settings, "compose").at(BufferId::vct_compose_color));
  for (double offset : {1e6, 1e9, 1e12}) {
    const Image moved = bufferImage(
        runCpuUntil(cornellAt(offset), settings, "compose").at(BufferId::vct_compose_color));
    EXPECT_LT(relMse(moved, atOrigin), 1e-6) << "offset " << offset;
  }
}

TEST(FarFromOrigin, PathTracingIsTheSameAtAnyOffset) {
  reference::PathTraceOptions options;
  options.spp = 8;
  options.bounces = 2;
  const Image atOrigin = reference::pathTrace(cornellAt(0.0), options).image;
  for (double offset : {1e6, 1e9, 1e12}) {
    const Image moved = reference::pathTrace(cornellAt(offset), options).image;
    // Same seed, same paths: only the rounding of coordinates relative to the centre differs.
    EXPECT_LT(relMse(moved, atOrigin), 1e-4) << "offset " << offset;
  }
}

}  // namespace
}  // namespace voxgi::test
