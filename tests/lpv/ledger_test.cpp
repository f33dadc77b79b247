// The energy ledger of a light propagation volume (validation/lpv/ledger.h, docs/lpv.md "Where
// the light goes") on a closed box lit by an emissive square: the injected flux is the emitted
// flux, and every step accounts for it — what the faces send is what the last step held (the
// energy normalisation; a quarter of it with Martin's Eq. 3.3), what arrives by the ledger's own
// face-by-face sum is what the propagate stage wrote, and the flux removed by the geometry volume,
// lost at the grid's border and still in flight adds up to what was injected.
#include <gtest/gtest.h>

#include "common/voxel_triangles.h"
#include "tests/test_scenes.h"
#include "validation/lpv/ledger.h"

namespace voxgi::test {
namespace {

// The walls of [0.15, 0.85]^3 facing in (albedo 0.5) and a 0.2 x 0.2 square of radiance
// (3, 2, 1) under the ceiling facing down, in a unit 16^3 grid.
Scene litBox() {
  std::vector<Triangle> walls;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.15, 0.85})
      for (Triangle t : quad(axis, side, {0.15, 0.15}, {0.85, 0.85})) {
        glm::dvec3 inward(0.0);
        inward[axis] = side < 0.5 ? 1.0 : -1.0;
        if (glm::dot(glm::cross(t[1] - t[0], t[2] - t[0]), inward) < 0.0) std::swap(t[1], t[2]);
        walls.push_back(t);
      }
  Material white;
  white.albedo = glm::vec3(0.5f);
  Scene scene = makeScene(walls, unitGrid(16), white);
  Material emitter;
  emitter.emission = {3.0f, 2.0f, 1.0f};
  scene.materials.push_back(emitter);
  Mesh light;
  light.positions = {{0.4, 0.8, 0.4}, {0.6, 0.8, 0.4}, {0.6, 0.8, 0.6}, {0.4, 0.8, 0.6}};
  light.triangles = {{0, 1, 2}, {0, 2, 3}};  // counter-clockwise from below: emits down
  light.material = 1;
  scene.meshes.push_back(light);
  return scene;
}

validation::Ledger ledgerOf(const Scene& scene, const Settings& settings) {
  const Technique& lpv = findTechnique("lpv");
  const BufferSet buffers = runCpuUntil(lpv, scene, settings, "propagate");
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  return validation::lpvLedger(StageContext{lpv, scene, settings, triangles}, buffers);
}

TEST(LpvLedger, AClosedBoxAccountsForTheEmittedFlux) {
  const Scene scene = litBox();
  for (const bool holpv : {false, true})
    for (const LpvNormalization normalization :
         {LpvNormalization::energy, LpvNormalization::thesis}) {
      Settings settings;
      settings.vct.emitters = EmitterLighting::voxels;  // the emitter's own VPLs, flux pi L A
      settings.lpv.history = LpvToggle::on;
      settings.lpv.steps = 12;
      settings.lpv.normalization = normalization;
      if (holpv) {
        settings.lpv.bands = 3;
        settings.lpv.directions = LpvDirections::twenty_six;
      }
      const validation::Ledger l = ledgerOf(scene, settings);
      const double keep = normalization == LpvNormalization::energy ? 1.0 : 0.25;
      for (int c = 0; c < 3; ++c) {
        const double emitted = M_PI * scene.materials[1].emission[c] * 0.2 * 0.2;
        const std::string what = std::string(holpv ? "holpv" : "lpv") + " colour " +
                                 std::to_string(c) + " keep " + std::to_string(keep);
        EXPECT_NEAR(l.emitted[c], emitted, 1e-6 * emitted) << what;
        // Inside the grid, up to the fixed point's rounding.
        EXPECT_NEAR(l.injected[c], emitted, 1e-5 * emitted) << what;
        double previous = l.injected[c], removed = 0.0, left = 0.0;
        for (const validation::LedgerStep& s : l.steps) {
          EXPECT_NEAR(s.sent[c], keep * previous, 1e-5 * emitted) << what << " step " << s.step;
          EXPECT_NEAR(s.arrived[c], s.volume[c], 1e-5 * emitted) << what << " step " << s.step;
          EXPECT_GE(s.removed[c], 0.0);
          removed += s.removed[c];
          left += s.left[c];
          previous = s.volume[c];
        }
        // Occlusion from the second step on: the walls remove light (measured 10 % of it for lpv
        // and 5 % for holpv in 12 steps; the thesis's weights lose most before it gets there).
        EXPECT_GT(removed, (keep == 1.0 ? 0.02 : 0.002) * emitted) << what;
        const double lostToWeights = (1.0 - keep) * (l.injected[c] + [&] {
                                       double held = 0.0;
                                       for (size_t k = 0; k + 1 < l.steps.size(); ++k)
                                         held += l.steps[k].volume[c];
                                       return held;
                                     }());
        EXPECT_NEAR(removed + left + lostToWeights + previous, l.injected[c], 1e-4 * emitted)
            << what;
        // Shading is linear in the volume: the steps' readings add up to the accumulated one's.
        double read = l.readInjected[c];
        for (const validation::LedgerStep& s : l.steps) read += s.read[c];
        EXPECT_NEAR(read, l.read[c], 1e-4 * std::abs(l.read[c]) + 1e-6 * emitted) << what;
      }
    }
}

}  // namespace
}  // namespace voxgi::test
