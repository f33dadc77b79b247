// The planner in time on the GPU backend (llvmpipe through EGL): each technique's motion sequence
// (tests/frame_sequences.h) reached incrementally equals the frames run from scratch on the same
// backend, word for word — voxelize's partial update included, whose integer sums make it exact.
#include <gtest/gtest.h>

#include "gpu/backend.h"
#include "tests/frame_sequences.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

class GpuFramePlan : public testing::TestWithParam<TechniqueCase> {};

TEST_P(GpuFramePlan, IncrementalFramesEqualFramesFromScratch) {
  gpu::GpuBackend gpu(glContext(gpu::GlPlatform::egl));
  expectIncrementalFramesEqualScratch(GetParam(), gpu);
}

INSTANTIATE_TEST_SUITE_P(Techniques, GpuFramePlan, testing::ValuesIn(allTechniqueCases("motion")),
                         [](const testing::TestParamInfo<TechniqueCase>& p) {
                           return p.param.label;
                         });

TEST(GpuFramePlan, CarriedLightIsTheSameFromScratch) {
  gpu::GpuBackend gpu(glContext(gpu::GlPlatform::egl));
  for (const TechniqueCase& c : requiredCases("svo", "motion"))
    expectCarriedFramesEqualScratch(c, gpu);
}

TEST(GpuFramePlan, LightVoxelsRelightsOnlyWhatTheMovedMeshCanReach) {
  gpu::GpuBackend gpu(glContext(gpu::GlPlatform::egl));
  expectPartialRelightEqualsScratch(gpu);
}

}  // namespace
}  // namespace voxgi::test
