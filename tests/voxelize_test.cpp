// CPU voxelize: results checked against independent computations (analytic coverage, area
// conservation, a double-precision separating-axis test written here), plus determinism.
#include <random>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/scene_io/scene_load.h"
#include "shaders/shared/voxelize_kernel.h"
#include "shaders/shared/voxelize_layout.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr double kUnit = 65536.0;  // fixed-point units per h^2

uint32_t weightAt(const BufferSet& b, const GridSpec& g, glm::ivec3 v) {
  return b.at(BufferId::common_voxelize_weight_sum).words[g.index(v)];
}

// Independent closed triangle / closed box overlap in double (box [lo, lo+1]^3), with the
// signed separation so that near-ties can be excluded from the comparison.
double separation(const Triangle& t, glm::dvec3 lo) {
  const glm::dvec3 c = lo + glm::dvec3(0.5);
  const glm::dvec3 v[3] = {t[0] - c, t[1] - c, t[2] - c};
  const glm::dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  std::vector<glm::dvec3> axes = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, glm::cross(e[0], e[1])};
  for (const auto& edge : e)
    for (int k = 0; k < 3; ++k) {
      glm::dvec3 u(0.0);
      u[k] = 1.0;
      axes.push_back(glm::cross(u, edge));
    }
  double worst = -1e300;
  for (const glm::dvec3& a : axes) {
    const double len = glm::length(a);
    if (len < 1e-12) continue;
    const double p0 = glm::dot(a, v[0]), p1 = glm::dot(a, v[1]), p2 = glm::dot(a, v[2]);
    const double r = 0.5 * (std::abs(a.x) + std::abs(a.y) + std::abs(a.z));
    const double s = std::max(std::min({p0, p1, p2}) - r, -r - std::max({p0, p1, p2}));
    worst = std::max(worst, s / len);
  }
  return worst;
}

TEST(Voxelize, AxisAlignedQuadCoversExactlyItsVoxelsWithTheirAreas) {
  // Quad z = 4.8 voxels, x, y in [4.16, 11.84] voxels on a 16^3 unit grid.
  const double h = 1.0 / 16;
  const Scene scene =
      makeScene(quad(2, 4.8 * h, {4.16 * h, 4.16 * h}, {11.84 * h, 11.84 * h}), unitGrid(16));
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const bool inside = k == 4 && i >= 4 && i <= 11 && j >= 4 && j <= 11;
        const uint32_t w = weightAt(b, scene.grid, {i, j, k});
        if (!inside) {
          ASSERT_EQ(w, 0u) << i << "," << j << "," << k;
          continue;
        }
        const double cx = (i == 4 || i == 11) ? 0.84 : 1.0, cy = (j == 4 || j == 11) ? 0.84 : 1.0;
        // Two triangles, each rounded once: at most one unit apart from the exact area.
        EXPECT_NEAR(w, cx * cy * kUnit, 2.0) << i << "," << j;
        EXPECT_FLOAT_EQ(
            b.at(BufferId::common_voxelize_opacity).get<float>(scene.grid.index({i, j, k}), 0),
            1.0f);
      }
}

TEST(Voxelize, AttributesAreTheMaterialsAndTheUnitNormal) {
  Material m;
  m.albedo = {0.25f, 0.5f, 0.75f};
  m.emission = {3.0f, 2.0f, 1.0f};
  const Scene scene = makeScene(quad(1, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16), m);
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  const size_t e = scene.grid.index({8, 4, 8});
  ASSERT_GT(b.at(BufferId::common_voxelize_weight_sum).words[e], 0u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(b.at(BufferId::common_voxelize_albedo).get<float>(e, c), m.albedo[c], 1e-4);
    EXPECT_NEAR(b.at(BufferId::common_voxelize_emission).get<float>(e, c), m.emission[c],
                1e-4 * 3.0);
  }
  // quad(1, ...) spans (z, x): its winding gives the -y normal.
  EXPECT_NEAR(std::abs(b.at(BufferId::common_voxelize_normal).get<float>(e, 1)), 1.0f, 1e-4);
  EXPECT_NEAR(b.at(BufferId::common_voxelize_normal).get<float>(e, 0), 0.0f, 1e-4);
}

// A wall at y = 0.3 over [0.1, 0.9]^2 and on it a lamp over [0.4, 0.6]^2 emitting (4, 2, 1)
// (material 1), in the unit grid of `resolution` voxels.
Scene lampOnAWall(int resolution) {
  Material wall, light;
  light.emission = {4.0f, 2.0f, 1.0f};
  Scene scene = makeScene(quad(1, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(resolution), wall);
  Mesh lamp =
      makeScene(quad(1, 0.3, {0.4, 0.4}, {0.6, 0.6}), unitGrid(resolution), light).meshes[0];
  lamp.material = 1;
  scene.materials.push_back(light);
  scene.meshes.push_back(lamp);
  return scene;
}

// voxelize.emission (docs/stages/voxelize.md): a light on a wall in one voxel layer. By default
// a voxel's emission is the mean over all its surfaces, so the wall halves the light where both
// fill a voxel; with `emitters` it is the mean over the emitting surfaces, the light's own, also
// in the voxels its edge only partly covers (60 % here).
TEST(Voxelize, AnEmitterOnAWallKeepsItsEmissionWithEmittersMean) {
  const Scene scene = lampOnAWall(16);
  const Material& light = scene.materials.at(1);
  const glm::ivec3 inside(8, 4, 8), edge(6, 4, 8);  // voxel 6 spans x in [0.375, 0.4375)
  for (const VoxelizeEmission mode : {VoxelizeEmission::surfaces, VoxelizeEmission::emitters}) {
    Settings settings;
    settings.voxelizeEmission = mode;
    settings.inspect = true;  // keeps the sums (Effect::voxel_sums)
    const BufferSet b = runCpuUntil(scene, settings, "voxelize");
    const Buffer& emission = b.at(BufferId::common_voxelize_emission);
    const bool emitters = mode == VoxelizeEmission::emitters;
    for (int c = 0; c < 3; ++c) {
      // Fixed-point weights: each triangle's area rounded to 2^-16 voxel faces.
      EXPECT_NEAR(voxelValue(emission, inside)[c], light.emission[c] * (emitters ? 1.0f : 0.5f),
                  1e-4f * light.emission[c]);
      EXPECT_NEAR(voxelValue(emission, edge)[c],
                  light.emission[c] * (emitters ? 1.0f : 0.6f / 1.6f), 1e-4f * light.emission[c]);
    }
    // The emitters' weight is the light's area in the voxel (0.6 voxel faces), whatever the mode.
    const Buffer& sum = b.at(BufferId::common_voxelize_emission_sum);
    EXPECT_NEAR(double(sum.words[4 * scene.grid.index(edge) + 3]) / 65536.0, 0.6, 1e-4);
  }
}

// A render leaves voxelize's sums out (Effect::voxel_sums off) and keeps them only in the blocks of
// 8^3 voxels the surface reaches; voxgi diff keeps them dense. Both give the same volumes, word for
// word, and the dense sums resolve voxel by voxel to those volumes (the blocks' sums land where
// they belong; the GPU diff compares the sums themselves with the GPU's dense images). Both modes,
// both emission means, a grid of 20 voxels (its last blocks partial) and the bunny at 40.
TEST(Voxelize, ReleasingTheSumsLeavesTheVolumesBitForBit) {
  Scene lamp = lampOnAWall(20);
  Scene bunny = loadScene(sourcePath("scenes/bunny.obj"));
  bunny.grid.resolution = 40;
  bunny.lights.push_back(testLight());
  using enum BufferId;
  const BufferId sums[] = {common_voxelize_weight_sum, common_voxelize_albedo_sum,
                           common_voxelize_normal_sum, common_voxelize_emission_sum};
  const BufferId volumes[] = {common_voxelize_opacity, common_voxelize_albedo,
                              common_voxelize_normal, common_voxelize_emission};
  for (const Scene* scene : {&lamp, &bunny})
    for (const VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased})
      for (const VoxelizeEmission mean : {VoxelizeEmission::surfaces, VoxelizeEmission::emitters}) {
        SCOPED_TRACE(std::string(scene == &lamp ? "lamp, " : "bunny, ") + voxelizeModeName(mode));
        Settings render;
        render.voxelizeMode = mode;
        render.voxelizeEmission = mean;
        Settings inspect = render;
        inspect.inspect = true;
        const BufferSet a = runCpuUntil(*scene, render, "voxelize");
        const BufferSet b = runCpuUntil(*scene, inspect, "voxelize");
        const bool emissive = scene == &lamp;
        for (const BufferId id : sums) {
          EXPECT_FALSE(a.contains(id)) << bufferSpec(id).qualifiedName();
          EXPECT_EQ(b.contains(id), emissive || id != common_voxelize_emission_sum);
        }
        for (const BufferId id : volumes) {
          if (!emissive && id == common_voxelize_emission) continue;
          EXPECT_TRUE(a.at(id).words == b.at(id).words) << bufferSpec(id).qualifiedName();
        }
        const Buffer &weight = b.at(common_voxelize_weight_sum),
                     &albedoSum = b.at(common_voxelize_albedo_sum),
                     &normalSum = b.at(common_voxelize_normal_sum);
        size_t occupied = 0;
        for (size_t e = 0; e < weight.elementCount(); ++e) {
          const uint32_t w = weight.words[e];
          occupied += w != 0u;
          const glm::uvec3 albedo(albedoSum.words[3 * e], albedoSum.words[3 * e + 1],
                                  albedoSum.words[3 * e + 2]);
          const glm::ivec3 normal(int32_t(normalSum.words[3 * e]),
                                  int32_t(normalSum.words[3 * e + 1]),
                                  int32_t(normalSum.words[3 * e + 2]));
          ASSERT_EQ(a.at(common_voxelize_opacity).get<float>(e, 0),
                    shared::resolveOpacity(w, mode == VoxelizeMode::antialiased))
              << "voxel " << e;
          ASSERT_EQ(a.at(common_voxelize_albedo).vec3At(e), shared::resolveAverage(albedo, w))
              << "voxel " << e;
          ASSERT_EQ(a.at(common_voxelize_normal).vec3At(e), shared::resolveNormal(normal, w))
              << "voxel " << e;
        }
        EXPECT_GT(occupied, 100u);
      }
}

TEST(Voxelize, NonEmissiveScenesGetNoEmissionBuffers) {
  const Scene scene = makeScene(quad(2, 0.5, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  EXPECT_FALSE(b.contains(BufferId::common_voxelize_emission));
  EXPECT_FALSE(b.contains(BufferId::common_voxelize_emission_sum));
}

TEST(Voxelize, TotalWeightIsTheSurfaceArea) {
  Scene scene = loadScene(sourcePath("scenes/bunny.obj"));
  scene.grid.resolution = 32;
  double area = 0.0;  // in voxel faces
  const double scale = scene.grid.resolution / scene.grid.size;
  for (const Mesh& m : scene.meshes)
    for (const auto& t : m.triangles)
      area += 0.5 *
              glm::length(glm::cross(m.positions[t.y] - m.positions[t.x],
                                     m.positions[t.z] - m.positions[t.x])) *
              scale * scale;
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
    const BufferSet b = runCpu(scene, mode);
    double total = 0.0;
    for (uint32_t w : b.at(BufferId::common_voxelize_weight_sum).words) total += w;
    EXPECT_NEAR(total / kUnit, area, area * 2e-3) << voxelizeModeName(mode);
  }
}

TEST(Voxelize, ConservativeMatchesAnIndependentDoubleSeparatingAxisTest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.5, 15.5);
  const GridSpec grid = unitGrid(16, 16.0);  // voxel-local = world
  size_t compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Triangle t;
    for (auto& p : t) p = {coord(rng), coord(rng), coord(rng)};
    if (trial % 4 == 0)
      t[2] = t[0] + 0.3 * (t[1] - t[0]) + glm::dvec3(0.01, -0.02, 0.015);  // sliver
    const Scene scene = makeScene({t}, grid);
    const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
    for (int k = 0; k < 16; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
          const double s = separation(t, glm::dvec3(i, j, k));
          if (std::abs(s) < 1e-4) continue;  // a tie: float and double may legitimately disagree
          ++compared;
          ASSERT_EQ(weightAt(b, grid, {i, j, k}) > 0, s <= 0.0)
              << "trial " << trial << " voxel " << i << "," << j << "," << k << " separation " << s;
        }
  }
  EXPECT_GT(compared, 100000u);
}

TEST(Voxelize, AntialiasedWallThroughVoxelCentresIsOpaqueInItsLayerOnly) {
  const double h = 1.0 / 16;
  const Scene scene =
      makeScene(quad(2, 8.5 * h, {2.0 * h, 2.0 * h}, {14.0 * h, 14.0 * h}), unitGrid(16));
  const BufferSet b = runCpu(scene, VoxelizeMode::antialiased);
  for (int k = 6; k <= 10; ++k) {
    const float o =
        b.at(BufferId::common_voxelize_opacity).get<float>(scene.grid.index({8, 8, k}), 0);
    EXPECT_NEAR(o, k == 8 ? 1.0f : 0.0f, 1e-3) << "layer " << k;
  }
}

TEST(Voxelize, BitIdenticalForAnyThreadCountAndRun) {
  Scene scene = loadScene(sourcePath("scenes/bunny.json"));
  scene.grid.resolution = 32;
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
    uint64_t reference = 0;
    for (size_t threads : {1u, 2u, 8u, 8u}) {
      // global_control lifts TBB's cap above the core count; the arena asks for that many threads.
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      tbb::task_arena arena(static_cast<int>(threads));
      const uint64_t h = arena.execute([&] { return hashBuffers(runCpu(scene, mode)); });
      if (reference == 0) reference = h;
      EXPECT_EQ(h, reference) << voxelizeModeName(mode) << " with " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace voxgi::test
