// The lanes (cpu/cone/cone_lanes.h) compute exactly what the shared marchCone computes: bit for
// bit, on every instruction set this CPU runs, on random cones through a lit Cornell box, for
// every kind of march and the settings that change the arithmetic (step factor, clearance,
// pyramid mode, ambient occlusion, step limit).
#include <bit>
#include <random>

#include <gtest/gtest.h>

#include "common/scene_io/scene_load.h"
#include "common/cone/cone_trace.h"
#include "cpu/cone/cone_lanes.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

void expectSameBits(const shared::ConeHit& lanes, const shared::ConeHit& scalar, size_t job) {
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(std::bit_cast<uint32_t>(lanes.radiance[k]),
              std::bit_cast<uint32_t>(scalar.radiance[k]))
        << "job " << job << " radiance " << k << ": " << lanes.radiance[k] << " vs "
        << scalar.radiance[k];
  EXPECT_EQ(std::bit_cast<uint32_t>(lanes.occlusion), std::bit_cast<uint32_t>(scalar.occlusion))
      << "job " << job << ": " << lanes.occlusion << " vs " << scalar.occlusion;
  EXPECT_EQ(std::bit_cast<uint32_t>(lanes.ambient), std::bit_cast<uint32_t>(scalar.ambient))
      << "job " << job;
}

// Random cones: origins anywhere in the grid and a little outside it, any direction, apertures
// from a pencil to a hemisphere's, lengths from a voxel to past the grid.
std::vector<cpu::ConeJob> randomCones(int n, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<cpu::ConeJob> jobs;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 origin = glm::vec3(unit(rng), unit(rng), unit(rng)) * (float(n) + 2.0f) - 1.0f;
    glm::vec3 d;
    do d = glm::vec3(unit(rng), unit(rng), unit(rng)) * 2.0f - 1.0f;
    while (glm::dot(d, d) > 1.0f || glm::dot(d, d) < 1e-4f);
    d = glm::normalize(d);
    // Axis-aligned directions too: their zero weights skip faces.
    if (i % 16 == 0) d = glm::vec3(0.0f, i % 32 == 0 ? 1.0f : -1.0f, 0.0f);
    const float tanHalf = std::pow(10.0f, unit(rng) * 3.5f - 3.0f);  // 0.001 .. 3.2
    const float maxDistance = i % 4 == 0 ? 1e30f : unit(rng) * 2.0f * float(n);
    jobs.push_back({origin, d, unit(rng) * 2.0f - 1.0f, tanHalf, maxDistance});
  }
  return jobs;
}

// The lit volumes the cones march through, as vct's light_voxels and mip (run up to mip, the
// fixture) leave them: the radiance and the pyramid `mode` asks for.
struct LitVolumes {
  BufferId radiance, pyramid;
};
LitVolumes litVolumes(MipMode mode) {
  return {BufferId::vct_light_voxels_radiance, mode == MipMode::isotropic
                                                   ? BufferId::vct_mip_radiance_mips
                                                   : BufferId::vct_mip_radiance_mips6};
}

struct Case {
  MipMode mip;
  float step;
  float clearance;
  AmbientOcclusion ao;
  int maxSteps;  // 0: the planned limit
};

TEST(ConeLanes, BitIdenticalToTheSharedMarch) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 32;
  const Case cases[] = {
      {MipMode::anisotropic, 0.5f, 0.0f, AmbientOcclusion::on, 0},
      {MipMode::isotropic, 1.0f, 0.0f, AmbientOcclusion::off, 0},
      {MipMode::anisotropic, 1.0f, 0.5f, AmbientOcclusion::on, 0},
      {MipMode::isotropic, 0.3f, 0.25f, AmbientOcclusion::on, 0},
      {MipMode::anisotropic, 2.0f, 0.0f, AmbientOcclusion::off, 7},
  };
  for (const Case& c : cases) {
    Settings settings;
    settings.vct.mip = c.mip;
    settings.vct.coneStep = c.step;
    settings.vct.coneClearance = c.clearance;
    settings.vct.ambientOcclusion = c.ao;
    const BufferSet buffers = runCpuUntil(scene, settings, "mip");
    const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
    const StageContext ctx{vct(), scene, settings, triangles};
    const ConeTraceSetup setup = prepareConeTrace(ctx);
    shared::ConeTraceParams params = setup.params;
    if (c.maxSteps > 0) params.maxSteps = c.maxSteps;
    params.shadowStrength = 1.5f;  // Kahl's strength, so that the falloff is not a constant
    const LitVolumes lit = litVolumes(settings.vct.mip);
    const cpu::ConeVolumes volumes(buffers.at(lit.radiance), buffers.at(lit.pyramid), c.mip,
                                   scene.grid.resolution, setup.lights, setup.cones);
    const std::vector<cpu::ConeJob> jobs = randomCones(scene.grid.resolution, 3000, 7);
    for (const int kind : {shared::kMarchRadiance, shared::kMarchFirstHit, shared::kMarchShadow,
                           shared::kMarchShadowKahl}) {
      std::vector<shared::ConeHit> scalar;
      size_t seen = 0;
      for (const cpu::ConeJob& j : jobs) {
        scalar.push_back(shared::marchCone(volumes, j.origin, j.direction, j.rise, j.tanHalf,
                                           j.maxDistance, kind, params));
        seen += scalar.back().occlusion > 0.0f;
      }
      // The cones meet the walls: the comparison is not between empty marches.
      EXPECT_GT(seen, jobs.size() / 4) << "kind " << kind;
      for (const cpu::SimdLevel level : cpu::runnableSimdLevels()) {
        SCOPED_TRACE(std::string(cpu::simdLevelName(level)) + ", kind " + std::to_string(kind));
        std::vector<shared::ConeHit> hits(jobs.size());
        cpu::marchCones(level, volumes, jobs, kind, params, hits);
        for (size_t i = 0; i < jobs.size(); ++i) expectSameBits(hits[i], scalar[i], i);
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
}

// A stream shorter than the lanes and an empty one, on every instruction set.
TEST(ConeLanes, ShortStreams) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 16;
  const Settings settings;
  const BufferSet buffers = runCpuUntil(scene, settings, "mip");
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{vct(), scene, settings, triangles};
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const LitVolumes lit = litVolumes(settings.vct.mip);
  const cpu::ConeVolumes volumes(buffers.at(lit.radiance), buffers.at(lit.pyramid),
                                 settings.vct.mip, 16, setup.lights, setup.cones);
  const std::vector<cpu::ConeJob> jobs = randomCones(16, 3, 11);
  for (const cpu::SimdLevel level : cpu::runnableSimdLevels()) {
    SCOPED_TRACE(cpu::simdLevelName(level));
    cpu::marchCones(level, volumes, {}, shared::kMarchRadiance, setup.params, {});
    std::vector<shared::ConeHit> hits(jobs.size());
    cpu::marchCones(level, volumes, jobs, shared::kMarchRadiance, setup.params, hits);
    for (size_t i = 0; i < jobs.size(); ++i) {
      const cpu::ConeJob& j = jobs[i];
      expectSameBits(hits[i],
                     shared::marchCone(volumes, j.origin, j.direction, j.rise, j.tanHalf,
                                       j.maxDistance, shared::kMarchRadiance, setup.params),
                     i);
    }
  }
}

}  // namespace
}  // namespace voxgi::test
