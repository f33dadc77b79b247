// The inject_geometry stage (docs/stages/lpv/inject_geometry.md) with the RSM texels' surfaces as
// blockers.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/lpv/light_scenes.h"

namespace voxgi::test {
namespace {

// inject_geometry.blockers=rsm: the texels' surfaces as blockers. Inside a closed box every wall is
// seen by a point light at its centre at cosines of at least 1/sqrt(3), so the blocker areas sum to
// the walls' area (6 x 9.6^2 cells^2), up to the midpoint rule's 6e-5 at 64^2 per face; the area-
// weighted normals, turned toward the light, cancel. A second light sees the same walls: each cell
// keeps one light's surfaces, so the total stays near that area instead of doubling (above it by
// what the larger of two samplings of a cell adds: measured +6.6 %).
TEST(InjectGeometry, RsmBlockersAreTheSurfacesTheLightsSee) {
  Scene scene = makeScene(cubeFaces(0.2, 0.8), unitGrid(16), grey(glm::vec3(0.5f)));
  scene.lights.push_back(pointLight({0.5, 0.5, 0.5}, glm::vec3(1.0f)));
  Settings settings;
  settings.lpv.rsmResolution = 64;
  settings.lpv.geometry = LpvGeometry::rsm;
  const double walls = 6.0 * 9.6 * 9.6;
  const auto areas = [](const Buffer& sums) {
    glm::dvec4 total(0.0);
    for (size_t e = 0; e < sums.elementCount(); ++e)
      for (int c = 0; c < 4; ++c) total[c] += sums.get<int32_t>(e, c) / 4194304.0;
    return total;
  };
  const glm::dvec4 one = areas(runCpuUntil(lpvTechnique(), scene, settings, "inject_geometry")
                                   .at(BufferId::lpv_inject_geometry_blocker_sum));
  EXPECT_NEAR(one.x, walls, 2e-4 * walls);
  for (int c = 1; c < 4; ++c) EXPECT_NEAR(one[c], 0.0, 1e-3) << "component " << c;
  scene.lights.push_back(pointLight({0.35, 0.6, 0.45}, glm::vec3(1.0f)));
  const glm::dvec4 two = areas(runCpuUntil(lpvTechnique(), scene, settings, "inject_geometry")
                                   .at(BufferId::lpv_inject_geometry_blocker_sum));
  EXPECT_GT(two.x, walls * (1.0 - 2e-4));
  EXPECT_LT(two.x, walls * 1.1) << "one light's surfaces per cell, not both";
}
}  // namespace
}  // namespace voxgi::test
