// Every CPU stage of every technique is bit-identical for any thread count and run
// (docs/architecture.md, "Determinism"), on the scenes each technique declares
// (tests/cases/<technique>.json, "determinism").
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "tests/technique_cases.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

class StageDeterminism : public testing::TestWithParam<TechniqueCase> {};

// Runs every stage of the technique's plan on 1, 2 and 8 threads; the buffers must hash the same.
TEST_P(StageDeterminism, BitIdenticalOn1_2_8Threads) {
  const TechniqueCase& c = GetParam();
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const Scene scene = caseScene(c);
  const Settings settings = caseSettings(c, scene);
  const std::string last = technique.steps().back()->qualifiedName();
  uint64_t reference = 0;
  for (int threads : {1, 2, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    tbb::task_arena arena(threads);
    const uint64_t h =
        arena.execute([&] { return hashBuffers(runCpuUntil(technique, scene, settings, last)); });
    if (threads == 1) reference = h;
    EXPECT_EQ(h, reference) << c.label << ", " << threads << " threads";
  }
}

INSTANTIATE_TEST_SUITE_P(Techniques, StageDeterminism,
                         testing::ValuesIn(allTechniqueCases("determinism")),
                         [](const testing::TestParamInfo<TechniqueCase>& p) {
                           return p.param.label;
                         });

}  // namespace
}  // namespace voxgi::test
