// The octree's effect planner (common/svo/plan.cpp; docs/effect-plan.md).
#include <gtest/gtest.h>

#include <array>

#include "common/scene_io/scene_load.h"
#include "common/svo/light_types.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/build_kernel.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// The Cornell box at 16^3 and 32^2.
Scene smallBox() {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 32;
  return scene;
}

// The octree's plan: emission and the specular cone from the materials of meshes and clouds, and
// the full pipeline gives the same image with the extra buffers.
TEST(SvoPlan, FollowsTheSceneAndTheFullPlanChangesNothing) {
  const Technique& svo = findTechnique("svo");
  const Scene scene = smallBox();
  Settings settings = techniqueDefaults(svo);
  const EffectPlan plan = svo.plan(scene, settings);
  EXPECT_TRUE(planItemIn(plan, "emission per pixel"));
  EXPECT_FALSE(planItemIn(plan, "specular cone"));
  const BufferSet lean = runCpuUntil(svo, scene, settings, "shade");
  EXPECT_FALSE(lean.contains(BufferId::svo_shade_indirect_specular));
  settings.planMode = PlanMode::full;
  const BufferSet full = runCpuUntil(svo, scene, settings, "shade");
  EXPECT_TRUE(full.contains(BufferId::svo_shade_indirect_specular));
  EXPECT_TRUE(full.contains(BufferId::svo_build_leaf_sums));
  EXPECT_TRUE(full.contains(BufferId::svo_propagate_gathered));
  EXPECT_TRUE(sameWords(lean, full, BufferId::svo_shade_color));
  Scene glossy = cornellBoxCloud(2000, true);
  EXPECT_TRUE(planItemIn(svo.plan(glossy, techniqueDefaults(svo)), "specular cone"));
}

// A render holds the leaves decoded from the sums and the gathered bricks; the sums and the
// per-leaf direct and gathered light, which no later stage reads, are kept where voxgi diff and
// dump compare them (the memory docs/benchmarks.md counts), and the image is the same either way.
// The leaves are each sum over the weight scale (times the emission scale), rounded to a half.
TEST(SvoPlan, KeepsTheSumsAndPerLeafLightOnlyWhereTheyAreCompared) {
  const Technique& svo = findTechnique("svo");
  const Scene scene = smallBox();
  Settings settings = techniqueDefaults(svo);
  const BufferSet lean = runCpuUntil(svo, scene, settings, "shade");
  for (const BufferId id : {BufferId::svo_build_leaf_sums, BufferId::svo_propagate_direct,
                            BufferId::svo_propagate_gathered})
    EXPECT_FALSE(lean.contains(id)) << bufferSpec(id).qualifiedName();
  settings.inspect = true;
  const BufferSet kept = runCpuUntil(svo, scene, settings, "shade");
  for (const BufferId id : {BufferId::svo_build_leaf_sums, BufferId::svo_propagate_direct,
                            BufferId::svo_propagate_gathered})
    EXPECT_TRUE(kept.contains(id)) << bufferSpec(id).qualifiedName();
  for (const BufferId id : {BufferId::svo_build_leaves, BufferId::svo_propagate_gathered_bricks,
                            BufferId::svo_shade_color})
    EXPECT_TRUE(sameWords(lean, kept, id)) << bufferSpec(id).qualifiedName();

  const Buffer& leaves = lean.at(BufferId::svo_build_leaves);
  const Words& sums = kept.at(BufferId::svo_build_leaf_sums).words;
  const Buffer& scales = kept.at(BufferId::svo_build_scales);
  const float weightScale = scales.get<float>(0, 0), emissionScale = scales.get<float>(0, 1);
  ASSERT_EQ(leaves.elementCount() * shared::kSumWords, sums.size());
  // Each leaf value's sum.
  std::array<int, svo::kLeafValues> sumOf{};
  sumOf[svo::kLeafOpacity] = shared::kSumOpacity;
  for (int c = 0; c < 3; ++c) {
    sumOf[size_t(svo::kLeafAlbedo + c)] = shared::kSumAlbedo + c;
    sumOf[size_t(svo::kLeafNormal + c)] = shared::kSumNormal + c;
    sumOf[size_t(svo::kLeafEmission + c)] = shared::kSumEmission + c;
  }
  size_t nonZero = 0;
  for (size_t e = 0; e < leaves.elementCount(); ++e)
    for (int c = 0; c < svo::kLeafValues; ++c) {
      const double sum = double(int32_t(sums[e * shared::kSumWords + size_t(sumOf[size_t(c)])]));
      const double value = sum / weightScale * (c >= svo::kLeafEmission ? emissionScale : 1.0f);
      nonZero += value != 0.0;
      ASSERT_EQ(leaves.get<float>(e, c), shared::roundToHalf(float(value)))
          << "leaf " << e << " component " << c;
    }
  EXPECT_GT(nonZero, 1000u);

  // The tree's bytes as `voxgi bench svo` and docs/benchmarks.md count them: the structure's words,
  // per leaf tile 8 leaves of 20 bytes and 8 radiance values of 8, a 27-texel brick of 8-byte
  // texels; per node tile 8 nodes of six 8-byte faces; and the scales' 8 bytes.
  const size_t leafTiles = lean.at(BufferId::svo_build_leaf_tiles).elementCount();
  const size_t nodeTiles = lean.at(BufferId::svo_build_tiles).elementCount();
  const size_t structure = 4 * (lean.at(BufferId::svo_build_nodes).words.size() +
                                lean.at(BufferId::svo_build_tiles).words.size() +
                                lean.at(BufferId::svo_build_leaf_tiles).words.size());
  size_t held = 0;
  for (const auto& [id, b] : lean)
    if (bufferSpec(id).shape == BufferShape::sparse) held += 4 * b.words.size();
  EXPECT_EQ(held, structure + leafTiles * (8 * 20 + 8 * 8 + 27 * 8) + nodeTiles * 8 * 6 * 8 + 8);
}

}  // namespace
}  // namespace voxgi::test
