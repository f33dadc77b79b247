// CPU propagate stage: propagate.steps gather steps of the shared kernel
// (shaders/shared/lpv/propagate_kernel.h), each cell of a step written by one task, between two
// volumes; the accumulated volume is added to in step order, so any thread count gives the same
// bits.
#include <tbb/blocked_range.h>

#include <cstring>

#include "common/lpv/inject.h"
#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/propagate_kernel.h"

namespace voxgi::cpu {
namespace {

template <int Coefficients>
struct PropagateVolumes {
  const std::vector<shared::PropagationEntry>& entries;
  const float* previous;  // the last step, 3C floats per cell
  float* next;
  float* accumulated;
  const Buffer* blocking;  // null without occlusion
  const shared::PropagateParams& params;
  int n, words;

  size_t index(glm::ivec3 v) const {
    return size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z));
  }
  static int coefficientCount() { return Coefficients; }
  static int colourCount() { return 3; }
  const shared::PropagationEntry& entryAt(int e) const { return entries[size_t(e)]; }
  float intensityAt(glm::ivec3 cell, int word) const {
    return previous[index(cell) * size_t(words) + size_t(word)];
  }
  glm::vec4 blockingAt(glm::ivec3 g) const {
    if (glm::any(glm::lessThan(g, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(g, glm::ivec3(n))))
      return glm::vec4(0.0f);
    const size_t e = index(g);
    return {blocking->get<float>(e, 0), blocking->get<float>(e, 1), blocking->get<float>(e, 2),
            blocking->get<float>(e, 3)};
  }
  void storeIntensity(glm::ivec3 cell, int word, float value) const {
    const size_t w = index(cell) * size_t(words) + size_t(word);
    next[w] = value;
    accumulated[w] = shared::accumulatedValue(accumulated[w], value, params);
  }
};

}  // namespace

void lpv::propagate(const StageContext& ctx, BufferSet& buffers) {
  const LpvSettings& s = ctx.settings.lpv;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(s);
  const int n = ctx.scene.grid.resolution;
  const int words = 3 * s.coefficients();
  const size_t count = size_t(n) * size_t(n) * size_t(n) * size_t(words);
  // The stage's buffers and the two step volumes it swaps between.
  const double stageBytes = double(stageBufferBytes(StageId::lpv_propagate, ctx.scene, ctx.plan));
  checkStageMemory(ctx, StageId::lpv_propagate, 1.0 + 2.0 * 4.0 * double(count) / stageBytes);
  voxgi::lpv::Propagation setup = voxgi::lpv::preparePropagation(s, n);

  std::vector<float> previous = voxgi::lpv::injectedVolume(ctx, buffers.at(sh.intensitySum));
  voxgi::lpv::prepareStorage(s, setup.params, previous);
  std::vector<float> next(count);
  Buffer accumulated(sh.accumulated, glm::ivec3(n));
  const bool history = ctx.plan.on(sh.history);
  Buffer steps = history ? Buffer(sh.steps, glm::ivec3(n, n, n * (setup.steps + 1))) : Buffer();
  float* acc = reinterpret_cast<float*>(accumulated.words.data());
  if (s.accumulateInjection == LpvToggle::on) std::memcpy(acc, previous.data(), count * 4);
  if (history) std::memcpy(steps.words.data(), previous.data(), count * 4);

  for (int step = 1; step <= setup.steps; ++step) {
    const bool occlude = voxgi::lpv::occludedStep(s, step);
    setup.params.occlude = occlude ? 1 : 0;
    const Buffer* blocking =
        occlude ? &buffers.at(BufferId::lpv_inject_geometry_blocking) : nullptr;
    const auto run = [&](const auto& volumes) {
      parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
        for (int row = rows.begin(); row != rows.end(); ++row)
          for (int x = 0; x < n; ++x)
            shared::propagateCell(volumes, glm::ivec3(x, row % n, row / n), setup.params);
      });
    };
    // The coefficient count as a constant: the compiler unrolls the kernel's loops.
    if (s.coefficients() == 4)
      run(PropagateVolumes<4>{setup.entries, previous.data(), next.data(), acc, blocking,
                              setup.params, n, words});
    else
      run(PropagateVolumes<9>{setup.entries, previous.data(), next.data(), acc, blocking,
                              setup.params, n, words});
    if (history) std::memcpy(steps.words.data() + size_t(step) * count, next.data(), count * 4);
    std::swap(previous, next);
  }
  buffers.put(std::move(accumulated));
  if (history) buffers.put(std::move(steps));
}

}  // namespace voxgi::cpu
