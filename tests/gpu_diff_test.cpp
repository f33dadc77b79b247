// voxgi diff against the plan: a backend that produces nothing, or what the plan does not ask
// for, fails the diff instead of passing it; a skipped stage is reported as skipped.
#include <gtest/gtest.h>

#include "cpu/backend.h"
#include "gpu/backend.h"
#include "gpu/volumes.h"
#include "tests/gl_contexts.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"

namespace voxgi::test {
namespace {

// The stage runs on the CPU, then `drop` removes its buffers (nothing written) or `extra` adds
// one the plan does not produce.
class FaultyBackend : public StageBackend {
 public:
  bool drop = false, extra = false;
  std::string name() const override { return "faulty"; }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override {
    cpu_.run(stage, ctx, buffers);
    if (drop)
      for (const BufferSpec* b : stageBuffers(stageSpec(stage))) buffers.take(b->id);
    if (extra)
      buffers.put(
          Buffer(BufferId::common_voxelize_emission, glm::ivec3(ctx.scene.grid.resolution)));
  }

 private:
  cpu::CpuBackend cpu_;
};

std::vector<validation::StageReport> diffVoxelize(StageBackend& cpu, StageBackend& gpu) {
  const Scene scene = litQuad();
  const Settings settings;
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  return validation::diffStages(StageContext{vct(), scene, settings, tris}, cpu, gpu,
                                {&stageSpec(StageId::common_voxelize)}, "");
}

bool statusSays(const validation::StageReport& r, const std::string& buffer,
                const std::string& text) {
  for (const auto& b : r.buffers)
    if (b.buffer == buffer) return b.status.find(text) != std::string::npos && !b.pass;
  return false;
}

TEST(GpuDiff, ABackendThatProducesNothingFails) {
  FaultyBackend cpu, gpu;
  cpu.drop = gpu.drop = true;
  const auto both = diffVoxelize(cpu, gpu);
  ASSERT_EQ(both.size(), 1u);
  EXPECT_FALSE(both[0].pass);
  EXPECT_TRUE(statusSays(both[0], "opacity", "planned, but missing on both backends"));
  cpu::CpuBackend reference;
  const auto one = diffVoxelize(reference, gpu);
  EXPECT_FALSE(one[0].pass);
  EXPECT_TRUE(statusSays(one[0], "opacity", "planned, but missing on gpu"));
}

TEST(GpuDiff, ABufferThePlanDoesNotProduceFails) {
  cpu::CpuBackend cpu;
  FaultyBackend gpu;
  gpu.extra = true;
  const auto r = diffVoxelize(cpu, gpu);
  EXPECT_FALSE(r[0].pass);
  EXPECT_TRUE(statusSays(r[0], "emission", "not planned, but produced on gpu"));
}

TEST(GpuDiff, TheRealBackendsPassAndSkippedStagesSaySo) {
  cpu::CpuBackend cpu;
  gpu::GpuBackend gpu(glContext(gpu::GlPlatform::egl));
  const auto r = diffVoxelize(cpu, gpu);
  EXPECT_TRUE(r[0].pass);
  for (const auto& b : r[0].buffers) {
    if (b.buffer.starts_with("emission")) {
      EXPECT_NE(b.status.find("not planned"), std::string::npos);
    }
  }
  const Scene scene = litQuad();
  const Settings settings;  // bounce.count=0
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const auto skipped = validation::diffStages(StageContext{vct(), scene, settings, tris}, cpu, gpu,
                                              {&stageSpec(StageId::vct_bounce)}, "");
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_NE(skipped[0].skipped.find("bounce.count=0"), std::string::npos) << skipped[0].skipped;
}

// A buffer of more components than a texture holds is refused by the texture path and travels
// as a storage buffer of its words (3-band RGB SH: 27 per cell).
TEST(GpuVolumes, MoreThanFourComponentsGoThroughStorageBuffers) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  context.makeCurrent();
  const gpu::Gl& gl = context.gl();
  EXPECT_THROW(gpu::floatFormat(27), std::logic_error);
  EXPECT_THROW(gpu::floatFormat(0), std::logic_error);
  BufferSpec sh = bufferSpec(BufferId::vct_light_voxels_radiance);
  sh.components = 27;
  Buffer b(sh, glm::ivec3(4));
  for (size_t w = 0; w < b.words.size(); ++w) b.words[w] = uint32_t(w * 2654435761u);
  EXPECT_THROW(gpu::uploadVolume(gl, b), std::logic_error);
  gpu::GlBuffer words(gl, gpu::uploadWords(gl, b));
  std::vector<uint32_t> back(b.words.size());
  gl.GetNamedBufferSubData(words.get(), 0, GLsizeiptr(back.size() * 4), back.data());
  EXPECT_TRUE(std::equal(back.begin(), back.end(), b.words.begin()));
}

}  // namespace
}  // namespace voxgi::test
