// CPU propagate stage: propagate.steps gather steps of the shared kernel
// (shaders/shared/lpv/propagate_kernel.h), run for a row of cells at a time in SIMD lanes
// (cpu/lpv/propagate_lanes.h, bit for bit the kernel), each row written by one task, between two
// volumes; the accumulated volume is added to in step order, so any thread count gives the same
// bits. The volumes live in the lanes' padded layout during the stage and are laid out as the
// registered buffers (a cell's words together) only where a buffer is written.
#include <tbb/blocked_range.h>

#include <cstring>

#include "common/lpv/inject.h"
#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "cpu/lpv/propagate_lanes_setup.h"
#include "cpu/stages.h"
#include "shaders/shared/lpv/storage.h"

namespace voxgi::cpu {
namespace {

using lpv_lanes::Layout;

// Every occluded step reads the same visibility of each entry at each cell; it is computed once
// ahead when it takes at most this much memory (a 32^3 HOLPV's 54 entries take 7.5 MB) and per
// step beyond (the same bits either way): out of the caches, reading it back each step costs more
// than computing it (64^3 LPV, AVX-512, 2 threads: 15 ms a step against 6).
constexpr double kVisibilityAheadBytes = 8.0 * 1024 * 1024;

// One step over rows [begin, end). With lpv.storage=f16 the lanes leave the raw sums in `next`
// and the rows are rounded here, as the kernel's storeIntensity does, before being accumulated.
void stepRows(const lpv_lanes::Step& step, const Layout& l, int words,
              const shared::PropagateParams& params, float* accumulated, int begin, int end) {
  lpv_lanes::propagateRows(simdLevel(), step, begin, end);
  if (step.accumulated) return;
  for (int row = begin; row != end; ++row)
    for (int w = 0; w < words; ++w)
      for (int x = 0; x < l.n; ++x) {
        const size_t i = l.index(words, row, w, x);
        const float stored = shared::storedValue(step.next[i], params);
        step.next[i] = stored;
        accumulated[i] = shared::accumulatedValue(accumulated[i], stored, params);
      }
}

}  // namespace

void lpv::propagate(const StageContext& ctx, BufferSet& buffers) {
  const LpvSettings& s = ctx.settings.lpv;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(s);
  const int n = ctx.scene.grid.resolution;
  const int words = 3 * s.coefficients();
  const size_t count = size_t(n) * size_t(n) * size_t(n) * size_t(words);
  const Layout layout(n);
  voxgi::lpv::Propagation setup = voxgi::lpv::preparePropagation(s, n);
  const bool occlusion = voxgi::lpv::occludedStep(s, setup.steps);
  const double visibilityBytes = 4.0 * double(layout.volumeFloats(int(setup.entries.size())));
  const bool visibilityAhead = occlusion && visibilityBytes <= kVisibilityAheadBytes;
  // The stage's buffers, the injected volume, the three volumes in the lanes' layout (previous,
  // next, accumulated), the geometry and the visibility computed ahead.
  const double stageBytes = double(stageBufferBytes(StageId::lpv_propagate, ctx.scene, ctx.plan));
  const double scratchBytes =
      4.0 * (double(count) + 3.0 * double(layout.volumeFloats(words)) +
             (occlusion ? 4.0 * double(n + 2) * double(n + 2) * double(layout.stride) : 0.0)) +
      (visibilityAhead ? visibilityBytes : 0.0);
  checkStageMemory(ctx, StageId::lpv_propagate, 1.0 + scratchBytes / stageBytes);

  // LPV_0 decoded from inject's sums straight into the lanes' layout (its zero pads leave the
  // storage scale and rounding as they are).
  std::vector<float> previous(layout.volumeFloats(words), 0.0f), next(previous.size(), 0.0f);
  voxgi::lpv::decodeInjected(ctx, buffers.at(sh.intensitySum),
                             [&](int row, int x, int word, float value) {
                               previous[layout.index(words, row, word, x)] = value;
                             });
  voxgi::lpv::prepareStorage(s, setup.params, previous);
  const bool history = ctx.plan.on(sh.history);
  Buffer steps = history ? Buffer(sh.steps, glm::ivec3(n, n, n * (setup.steps + 1))) : Buffer();
  if (history)
    lpv_lanes::fromLayout(layout, words, previous.data(),
                          reinterpret_cast<float*>(steps.words.data()));
  std::vector<float> accumulated =
      s.accumulateInjection == LpvToggle::on ? previous : std::vector<float>(previous.size(), 0.0f);
  const std::vector<float> geometry =
      occlusion ? lpv_lanes::geometryLayout(
                      layout, reinterpret_cast<const float*>(
                                  buffers.at(BufferId::lpv_inject_geometry_blocking).words.data()))
                : std::vector<float>();
  const std::vector<lpv_lanes::Entry> entries =
      lpv_lanes::laneEntries(setup.entries, s.coefficients());
  lpv_lanes::Step lanes;
  lanes.n = n;
  lanes.coefficients = s.coefficients();
  lanes.stride = layout.stride;
  lanes.entries = entries.data();
  lanes.entryCount = int(entries.size());
  lanes.clampNegative = setup.params.clampNegative != 0;
  std::vector<float> visibility;
  if (visibilityAhead) {
    visibility.resize(layout.volumeFloats(int(entries.size())));
    lanes.blocking = geometry.data();
    parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
      lpv_lanes::visibilityRows(simdLevel(), lanes, visibility.data(), rows.begin(), rows.end());
    });
  }

  for (int step = 1; step <= setup.steps; ++step) {
    lanes.previous = previous.data();
    lanes.next = next.data();
    lanes.accumulated = setup.params.halfPrecision ? nullptr : accumulated.data();
    const bool occluded = voxgi::lpv::occludedStep(s, step);
    lanes.blocking = occluded && !visibilityAhead ? geometry.data() : nullptr;
    lanes.visibility = occluded && visibilityAhead ? visibility.data() : nullptr;
    parallelFor(tbb::blocked_range<int>(0, n * n), [&](const auto& rows) {
      stepRows(lanes, layout, words, setup.params, accumulated.data(), rows.begin(), rows.end());
    });
    if (history)
      lpv_lanes::fromLayout(layout, words, next.data(),
                            reinterpret_cast<float*>(steps.words.data()) + size_t(step) * count);
    std::swap(previous, next);
  }
  Buffer out(sh.accumulated, glm::ivec3(n));
  lpv_lanes::fromLayout(layout, words, accumulated.data(),
                        reinterpret_cast<float*>(out.words.data()));
  buffers.put(std::move(out));
  if (history) buffers.put(std::move(steps));
}

}  // namespace voxgi::cpu
