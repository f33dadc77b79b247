// The CPU's propagation lanes (cpu/lpv/propagate_lanes.h) against the shared kernel run cell by
// cell (shared::propagateCell, the kernel the GPU runs): bit for bit, on every instruction set
// this CPU has (SSE2 always, which is what a CPU without AVX2 runs), for both coefficient counts
// and direction sets, with and without occlusion, clamping and the visibility computed ahead, on
// grids whose rows fill the lanes, leave them partly empty, or are a single cell.
#include <algorithm>
#include <bit>
#include <cstdlib>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "common/lpv/propagate.h"
#include "cpu/lpv/propagate_lanes_setup.h"
#include "shaders/shared/lpv/propagate_kernel.h"
#include "tests/lpv/kernel_volumes.h"

namespace voxgi::test {
namespace {

using cpu::SimdLevel;
using cpu::lpv_lanes::Layout;

struct Case {
  int bands;
  LpvDirections directions;
  bool occlusion, clamp, precomputedVisibility;
};

// One step on an n^3 grid of random intensities (a sixth of them exact zeros, signed) and
// blocking coefficients (some outside [0, 1], so that the clamp bites), both ways.
void expectLanesEqualTheKernel(const Case& c, int n, SimdLevel level) {
  LpvSettings s;
  s.bands = c.bands;
  s.directions = c.directions;
  s.clampNegative = c.clamp ? LpvToggle::on : LpvToggle::off;
  const voxgi::lpv::Propagation setup = voxgi::lpv::preparePropagation(s, n);
  const int C = s.coefficients(), words = 3 * C;
  const size_t cells = size_t(n) * size_t(n) * size_t(n);
  std::mt19937 random(uint32_t(n * 131 + C));
  std::uniform_real_distribution<float> value(-1.0f, 1.0f), block(-0.3f, 0.9f);
  std::vector<float> previous(cells * size_t(words));
  for (size_t i = 0; i < previous.size(); ++i)
    previous[i] = i % 6 == 0 ? (i % 12 == 0 ? 0.0f : -0.0f) : value(random);
  std::vector<glm::vec4> blocking(cells);
  for (glm::vec4& b : blocking) b = {block(random), block(random), block(random), block(random)};

  std::vector<float> want(previous.size());
  shared::PropagateParams params = setup.params;
  params.occlude = c.occlusion ? 1 : 0;
  const KernelVolumes scalar{
      setup.entries, previous, c.occlusion ? &blocking : nullptr, want, nullptr, params, n, C};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) shared::propagateCell(scalar, glm::ivec3(x, y, z), params);

  // The lanes' layout, with stale values in `next` where the step writes and zero pads.
  const Layout layout(n);
  std::vector<float> lanesPrevious(layout.volumeFloats(words), 0.0f);
  cpu::lpv_lanes::toLayout(layout, words, previous.data(), lanesPrevious.data());
  std::vector<float> next(layout.volumeFloats(words), 0.0f), stale(previous.size(), 7.0f);
  cpu::lpv_lanes::toLayout(layout, words, stale.data(), next.data());
  std::vector<float> accumulated(layout.volumeFloats(words), 0.0f), before(previous.size());
  for (size_t i = 0; i < before.size(); ++i) before[i] = float(i % 5);
  cpu::lpv_lanes::toLayout(layout, words, before.data(), accumulated.data());
  const std::vector<float> geometry =
      cpu::lpv_lanes::geometryLayout(layout, reinterpret_cast<const float*>(blocking.data()));
  const std::vector<cpu::lpv_lanes::Entry> entries = cpu::lpv_lanes::laneEntries(setup.entries, C);
  cpu::lpv_lanes::Step step;
  step.n = n;
  step.coefficients = C;
  step.stride = layout.stride;
  step.previous = lanesPrevious.data();
  step.next = next.data();
  step.accumulated = accumulated.data();
  step.entries = entries.data();
  step.entryCount = int(entries.size());
  step.clampNegative = c.clamp;
  std::vector<float> visibility;
  if (c.occlusion) step.blocking = geometry.data();
  if (c.occlusion && c.precomputedVisibility) {
    visibility.assign(layout.volumeFloats(int(entries.size())), 0.0f);
    cpu::lpv_lanes::visibilityRows(level, step, visibility.data(), 0, n * n);
    step.blocking = nullptr;
    step.visibility = visibility.data();
  }
  cpu::lpv_lanes::propagateRows(level, step, 0, n * n);
  std::vector<float> got(previous.size()), sums(previous.size());
  cpu::lpv_lanes::fromLayout(layout, words, next.data(), got.data());
  cpu::lpv_lanes::fromLayout(layout, words, accumulated.data(), sums.data());

  size_t wrong = 0;
  for (size_t i = 0; i < want.size() && wrong < 5; ++i)
    if (std::bit_cast<uint32_t>(got[i]) != std::bit_cast<uint32_t>(want[i]) ||
        std::bit_cast<uint32_t>(sums[i]) != std::bit_cast<uint32_t>(before[i] + want[i])) {
      ADD_FAILURE() << "cell " << i / size_t(words) << ", word " << i % size_t(words) << ": lanes "
                    << got[i] << " (accumulated " << sums[i] << "), kernel " << want[i];
      ++wrong;
    }
  for (int row = 0; row < n * n; ++row)  // the pads stay zero for the next step to read
    for (int w = 0; w < words; ++w)
      for (int x = n; x < layout.stride - 1; ++x)
        ASSERT_EQ(std::bit_cast<uint32_t>(next[layout.index(words, row, w, x)]), 0u)
            << "pad " << x << " of row " << row;
}

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.bands * c.bands << " coefficients, " << (c.directions == LpvDirections::six ? 6 : 26)
      << " directions";
}

class PropagateLanes : public testing::TestWithParam<Case> {};

TEST_P(PropagateLanes, EqualTheKernelBitForBitOnEveryInstructionSet) {
  for (const SimdLevel level : cpu::runnableSimdLevels())
    for (const int n : {1, 5, 16, 19}) {
      SCOPED_TRACE(std::string(cpu::simdLevelName(level)) + " at " + std::to_string(n) + "^3");
      expectLanesEqualTheKernel(GetParam(), n, level);
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, PropagateLanes,
                         testing::Values(Case{2, LpvDirections::six, false, false, false},
                                         Case{2, LpvDirections::six, true, false, false},
                                         Case{2, LpvDirections::six, true, true, true},
                                         Case{3, LpvDirections::twenty_six, true, false, false},
                                         Case{3, LpvDirections::twenty_six, true, false, true},
                                         Case{3, LpvDirections::six, false, true, false},
                                         Case{2, LpvDirections::twenty_six, true, true, true}),
                         [](const testing::TestParamInfo<Case>& p) {
                           const Case& c = p.param;
                           return "sh" + std::to_string(c.bands * c.bands) + "_" +
                                  (c.directions == LpvDirections::six ? "6" : "26") +
                                  (c.occlusion ? "_occluded" : "") + (c.clamp ? "_clamped" : "") +
                                  (c.precomputedVisibility ? "_visibility_ahead" : "");
                         });

// VOXGI_SIMD=sse2 lowers the level the stages use (ctest runs this binary's Simd tests with and
// without it); nothing raises it above what the CPU has.
TEST(Simd, TheEnvironmentCanOnlyLowerTheLevel) {
  const char* forced = std::getenv("VOXGI_SIMD");
  if (forced && std::string(forced) == "sse2")
    EXPECT_EQ(cpu::simdLevel(), SimdLevel::sse2);
  else
    EXPECT_EQ(cpu::simdLevel(), cpu::detectedSimdLevel());
  EXPECT_LE(cpu::simdLevel(), cpu::detectedSimdLevel());
}

// What this CPU lets the lanes' tests hold to the shared kernels' bits: they run every level of
// cpu::runnableSimdLevels() (the cone march, the gather, the shadow rays, voxel light, LPV
// propagation), and a level the CPU lacks is reported as skipped here, so that a run on a machine
// without AVX-512 or AVX2 says what it did not exercise (ctest lists the skipped levels).
class SimdLevels : public testing::TestWithParam<SimdLevel> {};

TEST_P(SimdLevels, TheLanesTestsRunThisLevel) {
  const SimdLevel level = GetParam();
  const std::vector<SimdLevel> runnable = cpu::runnableSimdLevels();
  if (level > cpu::detectedSimdLevel())
    GTEST_SKIP() << "this CPU has no " << cpu::simdLevelName(level)
                 << ": the lanes' tests did not run it";
  EXPECT_NE(std::find(runnable.begin(), runnable.end(), level), runnable.end());
}

INSTANTIATE_TEST_SUITE_P(Simd, SimdLevels,
                         testing::Values(SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512),
                         [](const testing::TestParamInfo<SimdLevel>& p) {
                           return std::string(cpu::simdLevelName(p.param));
                         });

}  // namespace
}  // namespace voxgi::test
