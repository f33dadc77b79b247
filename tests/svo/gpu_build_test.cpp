// The octree's GPU build (gpu/svo/octree.h) against the CPU's, on both GL platforms: the GPU
// allocates tiles with atomics in any order, and in the canonical form every word — nodes,
// neighbours, tile records and leaf sums — equals the CPU build's (docs/svo.md).
#include <random>

#include <gtest/gtest.h>

#include "cpu/svo/octree.h"
#include "gpu/svo/octree.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

std::vector<shared::SvoSample> scattered(int depth, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float n = float(1 << depth);
  std::vector<shared::SvoSample> out(count);
  for (size_t i = 0; i < count; ++i) {
    glm::vec3 p;
    if (i % 2 == 0) {  // a plane across the grid, and points anywhere (some past its faces)
      p = glm::vec3(u(rng) * n, 0.37f * n, u(rng) * n);
    } else {
      p = glm::vec3(u(rng), u(rng), u(rng)) * (n + 2.0f) - 1.0f;
    }
    const float r = 0.2f + 0.8f * u(rng);
    out[i].position = p;
    out[i].edge = r;
    out[i].albedo = glm::vec3(u(rng), u(rng), u(rng));
    out[i].density = 1.0f / r;
    out[i].normal = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) - 0.5f);
    out[i].emission = i % 7 == 0 ? glm::vec3(u(rng)) : glm::vec3(0.0f);
  }
  return out;
}

class GpuSvoBuild : public testing::TestWithParam<gpu::GlPlatform> {};

TEST_P(GpuSvoBuild, CanonicalFormEqualsTheCpuBuildWordForWord) {
  for (const int depth : {2, 5, 6}) {
    SCOPED_TRACE("depth " + std::to_string(depth));
    const auto samples = scattered(depth, 6000, uint32_t(depth));
    const cpu::svo::Octree cpu = cpu::svo::buildOctree(samples, depth);
    const Words cpuSums = cpu::svo::accumulateLeaves(cpu, samples, 4096.0f, "test");
    const svo::OctreeWords gpu =
        gpu::svo::buildOctree(glContext(GetParam()), samples, depth, 4096.0f, "test");
    ASSERT_EQ(gpu.tiles.size(), cpu.tiles.size());
    ASSERT_EQ(gpu.leafTiles.size(), cpu.leafTiles.size());
    EXPECT_EQ(gpu.tiles, cpu.tiles);
    EXPECT_EQ(gpu.leafTiles, cpu.leafTiles);
    EXPECT_EQ(gpu.nodes, cpu.nodes);
    EXPECT_EQ(gpu.sums, cpuSums);
  }
}

INSTANTIATE_TEST_SUITE_P(Platforms, GpuSvoBuild,
                         testing::Values(gpu::GlPlatform::osmesa, gpu::GlPlatform::egl),
                         [](const auto& p) { return std::string(gpu::glPlatformName(p.param)); });

}  // namespace
}  // namespace voxgi::test
