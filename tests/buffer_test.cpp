#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "common/buffer.h"
#include "common/mips.h"
#include "common/stage.h"
#include "common/technique.h"
#include "validation/comparisons.h"

namespace voxgi {
namespace {

TEST(Stages, EveryBufferHasAComparisonWithAReason) {
  for (const BufferSpec& b : bufferSpecs()) {
    const auto& c = validation::comparisonFor(b.id);
    EXPECT_TRUE(c.buffer == b.id) << b.name;
    EXPECT_FALSE(c.reason.empty()) << b.name;
    if (b.type != ScalarType::f32 && b.type != ScalarType::f16) {
      EXPECT_EQ(c.metric, validation::Metric::exact) << b.name;
    }
  }
  EXPECT_NE(findStage("common", "voxelize"), nullptr);
  EXPECT_EQ(findStage("vct", "voxelize"), nullptr);
  EXPECT_EQ(findStage("common", "nonexistent"), nullptr);
}

TEST(Buffer, TypedWordsRoundTrip) {
  Buffer b(BufferId::common_voxelize_normal_sum, glm::ivec3(2));
  EXPECT_EQ(b.words.size(), 8u * 3u);
  b.set<int32_t>(5, 2, -7);
  EXPECT_EQ(b.get<int32_t>(5, 2), -7);
  EXPECT_EQ(b.value(5, 2), -7.0);
}

// An f16 buffer packs two halves a word, the low half first, and stores the nearest half (IEEE
// binary16 bit patterns written out by hand).
TEST(Buffer, HalvesPackTwoAWordRoundedToNearestEven) {
  Buffer b(BufferId::svo_propagate_radiance, glm::ivec3(3, 1, 1));
  ASSERT_TRUE(b.halves());
  EXPECT_EQ(b.words.size(), 3u * 2u);
  b.set(1, 0, 1.0f);                          // 0x3c00
  b.set(1, 1, -2.0f);                         // 0xc000
  b.set(1, 2, 1.0f / 3.0f);                   // 0x3555 = 0.333251953125
  b.set(1, 3, 1.0f + std::ldexp(1.0f, -11));  // a tie: to even, 1.0
  EXPECT_EQ(b.words[2], 0xc0003c00u);
  EXPECT_EQ(b.words[3], 0x3c003555u);
  EXPECT_EQ(b.get<float>(1, 2), 0.333251953125f);
  EXPECT_EQ(b.bitsAt(1, 1), 0xc000u);
  b.set(2, 0, 1.0f + 3.0f * std::ldexp(1.0f, -11));  // a tie: to even, 1 + 2^-9
  b.set(2, 1, 70000.0f);                             // beyond 65504: infinity
  b.set(2, 2, std::ldexp(1.0f, -24));                // the smallest subnormal
  b.set(2, 3, std::ldexp(1.0f, -26));                // below half of it: zero
  EXPECT_EQ(b.words[4], 0x7c003c02u);
  EXPECT_EQ(b.words[5], 0x00000001u);
  EXPECT_EQ(b.value(2, 2), std::ldexp(1.0, -24));
  EXPECT_EQ(b.words[0], 0u);  // setting element 1 left element 0 alone

  const Words floats = floatWords(b);
  ASSERT_EQ(floats.size(), 12u);
  EXPECT_EQ(std::bit_cast<float>(floats[5]), -2.0f);
  EXPECT_EQ(std::bit_cast<float>(floats[8]), 1.0f + std::ldexp(1.0f, -9));
}

TEST(Buffer, ShapesAndStageBytes) {
  EXPECT_EQ(shapeElements(BufferShape::volume, 8, {}), 512u);
  EXPECT_EQ(shapeElements(BufferShape::mips, 8, {}), 64u + 8u + 1u);
  EXPECT_EQ(shapeElements(BufferShape::mips6, 8, {}), 6u * (64u + 8u + 1u));
  EXPECT_EQ(shapeElements(BufferShape::image, 8, {5, 3}), 15u);
  EXPECT_EQ(mipLevelOffset(8, 3, 6), 6u * (64u + 8u));
  Scene scene;
  scene.grid.resolution = 4;
  scene.lights.emplace_back().intensity = glm::vec3(1.0f);  // unlit: no voxelize (EffectPlan::dark)
  Settings settings;
  const Technique& vct = findTechnique("vct");
  // A render plans the volumes alone (opacity, albedo, normal); voxgi diff the sums beside them.
  EXPECT_EQ(stageBufferBytes(StageId::common_voxelize, scene, vct.plan(scene, settings)),
            64u * 4u * (1 + 3 + 3));
  settings.inspect = true;
  EXPECT_EQ(stageBufferBytes(StageId::common_voxelize, scene, vct.plan(scene, settings)),
            64u * 4u * (1 + 3 + 3 + 1 + 3 + 3));
  // bounce produces nothing unless asked, then the radiance and the pyramid mip.mode picks.
  EXPECT_EQ(stageBufferBytes(StageId::vct_bounce, scene, vct.plan(scene, settings)), 0u);
  settings.vct.bounceCount = 2;
  EXPECT_EQ(stageBufferBytes(StageId::vct_bounce, scene, vct.plan(scene, settings)),
            4u * 4u * (64u + 6u * (8u + 1u)));
  scene.materials.push_back({});
  scene.materials[0].emission = glm::vec3(1.0f);
  scene.meshes.push_back({"m", {glm::dvec3(0.0)}, {glm::uvec3(0u)}, 0, {}});
  // The emission sum's fourth word is the emitting surfaces' weight (voxelize.emission).
  EXPECT_EQ(stageBufferBytes(StageId::common_voxelize, scene, vct.plan(scene, settings)),
            64u * 4u * (1 + 3 + 3 + 4 + 1 + 3 + 3 + 3));
}

}  // namespace
}  // namespace voxgi
