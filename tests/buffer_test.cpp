#include <gtest/gtest.h>

#include "common/buffer.h"
#include "validation/comparisons.h"

namespace voxgi {
namespace {

TEST(Stages, EveryBufferHasAComparisonWithAReason) {
  for (const BufferSpec& b : bufferSpecs()) {
    const auto& c = validation::comparisonFor(b.stage, b.name);
    EXPECT_FALSE(c.reason.empty()) << b.name;
    if (b.type != ScalarType::f32) {
      EXPECT_EQ(c.metric, validation::Metric::exact) << b.name;
    }
  }
  EXPECT_NE(findStage("voxelize"), nullptr);
  EXPECT_EQ(findStage("nonexistent"), nullptr);
}

TEST(Buffer, TypedWordsRoundTrip) {
  Buffer b(bufferSpec("voxelize", "normal_sum"), glm::ivec3(2));
  EXPECT_EQ(b.words.size(), 8u * 3u);
  b.set<int32_t>(5, 2, -7);
  EXPECT_EQ(b.get<int32_t>(5, 2), -7);
  EXPECT_EQ(b.value(5, 2), -7.0);
  EXPECT_EQ(stageBufferBytes("voxelize", glm::ivec3(4), true),
            64u * 4u * (1 + 3 + 3 + 3 + 1 + 3 + 3 + 3));
  EXPECT_EQ(stageBufferBytes("voxelize", glm::ivec3(4), false), 64u * 4u * (1 + 3 + 3 + 1 + 3 + 3));
}

}  // namespace
}  // namespace voxgi
