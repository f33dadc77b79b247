// The diff engine: identical buffers pass, an injected difference fails unless the stage's tie
// classifier calls it a tie, and the voxelize classifier recognises near-boundary voxels.
#include <gtest/gtest.h>

#include <cmath>

#include "common/camera_geometry.h"
#include "common/voxel_triangles.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"

namespace voxgi::test {
namespace {

const StageSpec& voxelize() {
  return stageSpec(StageId::common_voxelize);
}
// The plan voxgi diff runs under (Settings::inspect): the sums are compared.
EffectPlan plan(const Scene& scene) {
  Settings settings;
  settings.inspect = true;
  return vct().plan(scene, settings);
}

TEST(Diff, IdenticalBuffersPass) {
  const Scene scene = litQuad();
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  const auto report = validation::compareStage(voxelize(), plan(scene), b, b, {});
  EXPECT_TRUE(report.pass);
  for (const auto& r : report.buffers) {
    if (r.buffer.starts_with("emission")) {
      EXPECT_NE(r.status, "compared");
    } else {
      EXPECT_EQ(r.differing, 0u);
    }
  }
}

TEST(Diff, InjectedDifferencesFailUnlessTheyAreTies) {
  const Scene scene = litQuad();
  const BufferSet cpu = runCpu(scene, VoxelizeMode::conservative);
  BufferSet gpu = cpu;
  Buffer weight = gpu.take(BufferId::common_voxelize_weight_sum);
  weight.words[123] += 1;
  gpu.put(std::move(weight));
  Buffer albedo = gpu.take(BufferId::common_voxelize_albedo);
  albedo.set<float>(77, 1, std::nextafter(albedo.get<float>(77, 1), 2.0f));  // 1 ULP: allowed
  gpu.put(std::move(albedo));
  auto noTies = [](size_t) { return false; };
  auto allTies = [](size_t) { return true; };
  const auto failing = validation::compareStage(voxelize(), plan(scene), cpu, gpu, noTies);
  EXPECT_FALSE(failing.pass);
  for (const auto& r : failing.buffers) {
    if (r.buffer == "weight_sum") {
      EXPECT_EQ(r.differing, 1u);
      EXPECT_EQ(r.nonTies, 1u);
      EXPECT_EQ(r.worstElement, 123);
      EXPECT_DOUBLE_EQ(r.maxAbsDiff, 1.0);
    }
    if (r.buffer == "albedo") {
      EXPECT_EQ(r.differing, 0u);
      EXPECT_EQ(r.maxUlp, 1.0);
    }
  }
  // Only the out-of-tolerance voxel is recorded (what the dump's classification grid shows).
  ASSERT_EQ(failing.outside.size(), 1u);
  EXPECT_EQ(failing.outside.at(123), validation::ElementClass::not_a_tie);
  EXPECT_TRUE(validation::compareStage(voxelize(), plan(scene), cpu, gpu, allTies).pass);
  // A voxel differing in several buffers is classified once.
  Buffer albedoSum = gpu.take(BufferId::common_voxelize_albedo_sum);
  albedoSum.words[3 * 123] += 1;
  gpu.put(std::move(albedoSum));
  int calls = 0;
  const auto counted = validation::compareStage(voxelize(), plan(scene), cpu, gpu, [&](size_t) {
    ++calls;
    return true;
  });
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(counted.pass);
  gpu.take(BufferId::common_voxelize_normal);
  EXPECT_FALSE(validation::compareStage(voxelize(), plan(scene), cpu, gpu, allTies).pass);
}

// A buffer stored as halves (svo's node faces, max_rel 1e-5) allows one ULP of a half where the
// two backends' floats round to neighbouring halves, and no more.
TEST(Diff, HalvesAllowOneUlpOfTheirRounding) {
  const Scene scene = litQuad();
  const Technique& svo = findTechnique("svo");
  const EffectPlan svoPlan = svo.plan(scene, techniqueDefaults(svo));
  BufferSet cpu;
  Buffer faces(BufferId::svo_mip_node_faces, glm::ivec3(2, 1, 1));
  for (int c = 0; c < faces.components(); ++c) faces.set(0, c, 1.0f);  // halves 0x3c00
  cpu.put(faces);                                                      // element 1 stays zero
  const auto withFace = [&](size_t e, int c, float v) {
    BufferSet gpu = cpu;
    Buffer f = gpu.take(BufferId::svo_mip_node_faces);
    f.set(e, c, v);
    gpu.put(std::move(f));
    return validation::compareStage(stageSpec(StageId::svo_mip), svoPlan, cpu, gpu, {});
  };
  const float ulp = std::ldexp(1.0f, -10);  // of a half in [1, 2)
  const validation::StageReport one = withFace(0, 5, 1.0f + ulp);
  EXPECT_TRUE(one.pass);
  EXPECT_EQ(one.buffers.at(0).maxUlp, 1.0);  // counted in ULPs of a half
  const validation::StageReport two = withFace(0, 5, 1.0f + 2.0f * ulp);
  EXPECT_FALSE(two.pass);
  EXPECT_EQ(two.buffers.at(0).maxUlp, 2.0);
  EXPECT_TRUE(withFace(0, 5, 1.0f - ulp / 2.0f).pass);  // the next half down, in [0.5, 1)
  // Where every value is tiny the allowance is one subnormal half's spacing, 2^-24.
  EXPECT_TRUE(withFace(1, 3, std::ldexp(1.0f, -24)).pass);
  EXPECT_FALSE(withFace(1, 3, std::ldexp(1.0f, -23)).pass);
}

TEST(Diff, VoxelizeTiesAreTheVoxelsOnADecisionBoundary) {
  const double h = 1.0 / 16;
  // A wall exactly on the face between layers 7 and 8: both layers touch it at separation 0.
  const Scene scene =
      makeScene(quad(2, 8.0 * h, {2.3 * h, 2.3 * h}, {13.7 * h, 13.7 * h}), unitGrid(16));
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  Settings settings;
  const auto classify = validation::voxelizeTies(StageContext{vct(), scene, settings, tris});
  EXPECT_TRUE(classify(scene.grid.index({8, 8, 7})));
  EXPECT_TRUE(classify(scene.grid.index({8, 8, 8})));
  EXPECT_FALSE(classify(scene.grid.index({8, 8, 5})));    // far from the wall
  EXPECT_FALSE(classify(scene.grid.index({15, 15, 8})));  // beside it, clearly separated
}

// The gbuffer's disc rule (validation/edge_ties.cpp): a pixel whose backends saw different
// surfaces, one a point cloud's disc, is a tie only at a disc's rim or where both surfaces lie
// at depths the GPU's depth buffer cannot separate.
TEST(Diff, DiscTiesAreRimsAndDepthsTooCloseToTell) {
  Scene scene = makeScene(quad(2, 0.05, {0.0, 0.0}, {0.1, 0.1}), unitGrid(16));  // one far wall
  scene.lights.push_back(testLight());
  scene.camera.position = {0.5, 0.5, 2.0};
  scene.camera.lookAt = {0.5, 0.5, 0.5};
  scene.camera.width = scene.camera.height = 32;
  PointCloud cloud;
  cloud.name = "two discs";
  // Disc 0 facing the camera; disc 1 in its plane, overlapping it; disc 2 a voxel behind.
  for (const glm::dvec3 c : {glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0.53, 0.5, 0.5),
                             glm::dvec3(0.5, 0.47, 0.5 - 1.0 / 16.0)}) {
    cloud.positions.push_back(c);
    cloud.normals.emplace_back(0.0f, 0.0f, 1.0f);
    cloud.radii.push_back(0.1f);
  }
  scene.pointClouds.push_back(cloud);
  const Technique& svo = findTechnique("svo");
  const Settings settings = techniqueDefaults(svo);
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{svo, scene, settings, tris};
  BufferSet cpu = runCpuUntil(svo, scene, settings, "gbuffer");
  BufferSet gpu = cpu;
  const uint32_t discs = 2;  // the wall's two triangles come first
  const Buffer& ids = cpu.at(BufferId::common_gbuffer_primitive_id);
  const size_t centre = 16 * 32 + 16;  // the pixel ray through the middle meets disc 0 or 1
  ASSERT_GT(ids.words[centre], discs);
  Buffer& other = const_cast<Buffer&>(gpu.at(BufferId::common_gbuffer_primitive_id));
  const validation::TieClassifier ties = validation::gbufferTies(ctx, cpu, gpu);
  // The other coplanar disc: the same depth, a tie.
  other.words[centre] = ids.words[centre] == discs + 1 ? discs + 2 : discs + 1;
  EXPECT_TRUE(ties(centre));
  // The disc a voxel behind: the depth buffer tells them apart, not a tie.
  other.words[centre] = discs + 3;
  EXPECT_FALSE(ties(centre));
  // The background where the CPU met a disc's inside: not a tie.
  other.words[centre] = 0;
  EXPECT_FALSE(ties(centre));
  // The background at a pixel whose ray meets disc 0 exactly at its rim: a tie.
  CameraGeometry g = prepareCameraGeometry(scene);
  const size_t rim = 16 * 32 + 27;
  const glm::vec3 d = g.camera.pixelDirection(27, 16);
  SurfaceDisc& disc = g.discs[0];
  const float t = glm::dot(glm::vec3(disc.center) - g.camera.origin, glm::vec3(disc.normal)) /
                  glm::dot(d, glm::vec3(disc.normal));
  scene.pointClouds[0].radii[0] =
      float(glm::length(g.camera.origin + d * t - glm::vec3(disc.center)) * scene.grid.voxelSize());
  const StageContext rimCtx{svo, scene, settings, tris};
  Buffer& cpuIds = const_cast<Buffer&>(cpu.at(BufferId::common_gbuffer_primitive_id));
  cpuIds.words[rim] = discs + 1;
  other.words[rim] = 0;
  EXPECT_TRUE(validation::gbufferTies(rimCtx, cpu, gpu)(rim));
}

}  // namespace
}  // namespace voxgi::test
