// Every stage after voxelize, GPU against the CPU reference (each fed the CPU's inputs), for every
// technique on the scenes, presets and GL platforms it declares (tests/cases/<technique>.json,
// "gpu"). Registered comparisons decide.
#include <sstream>

#include <gtest/gtest.h>

#include "tests/gl_contexts.h"
#include "tests/technique_cases.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::test {
namespace {

class GpuStages : public testing::TestWithParam<TechniqueCase> {};

// Every step of the technique after voxelize (whose own GPU test is tests/gpu_voxelize_test.cpp),
// GPU against CPU through the registered comparisons: each stage must pass.
TEST_P(GpuStages, AgreeWithCpu) {
  const TechniqueCase& c = GetParam();
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const Scene scene = caseScene(c);
  const Settings settings = caseSettings(c, scene);
  std::vector<std::string> stages;
  for (const StageSpec* s : technique.steps())
    if (s->id != StageId::common_voxelize) stages.push_back(s->qualifiedName());
  const auto reports = diffTechnique(technique, scene, settings,
                                     glContext(gpu::parseGlPlatform(c.platform)), stages);
  std::ostringstream table;
  validation::printReport(table, reports);
  ASSERT_EQ(reports.size(), stages.size()) << table.str();
  for (const auto& r : reports) EXPECT_TRUE(r.pass) << r.stage << "\n" << table.str();
}

INSTANTIATE_TEST_SUITE_P(Techniques, GpuStages, testing::ValuesIn(allTechniqueCases("gpu")),
                         [](const testing::TestParamInfo<TechniqueCase>& p) {
                           return p.param.label + "_" + p.param.platform;
                         });

}  // namespace
}  // namespace voxgi::test
