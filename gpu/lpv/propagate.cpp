// GPU propagate stage: LPV_0 from the fixed-point sums on the host (common/lpv/inject.h, as
// the CPU's), then shaders/lpv/propagate.comp propagate.steps times between two storage buffers,
// all on the GPU (under lpv.storage=f16 packed two halves a word); each step is copied into the
// history buffer when the plan keeps it.
#include <algorithm>
#include <cstring>
#include <vector>

#include "common/lpv/inject.h"
#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"
#include "shaders/shared/lpv/storage.h"

namespace voxgi::gpu {

void lpv::propagate(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::lpv_propagate);
  const LpvSettings& s = ctx.settings.lpv;
  const voxgi::lpv::ShBuffers sh = voxgi::lpv::shBuffers(s);
  const int n = ctx.scene.grid.resolution;
  voxgi::lpv::Propagation setup = voxgi::lpv::preparePropagation(s, n);
  std::vector<float> initial = voxgi::lpv::injectedVolume(ctx, buffers.at(sh.intensitySum));
  voxgi::lpv::prepareStorage(s, setup.params, initial);
  // A cell's words: its f32 values, or under lpv.storage=f16 its values packed two halves a word
  // (shaders/shared/lpv/storage.h), which halves the volumes' memory on the GPU.
  const int values = 3 * setup.params.coefficients;
  const bool packed = setup.params.halfPrecision != 0;
  const size_t cells = size_t(n) * size_t(n) * size_t(n);
  std::vector<uint32_t> words = packed ? voxgi::lpv::packStoredVolume(initial, values, setup.params)
                                       : std::vector<uint32_t>(initial.size());
  if (!packed) std::memcpy(words.data(), initial.data(), words.size() * 4);
  const size_t bytes = words.size() * 4;
  const bool history = ctx.plan.on(sh.history);

  requireStorageBlock(gl, ctx, bytes, "the SH volumes");
  GlBuffer entryBlock(gl, createBlock(gl, setup.params, setup.entries));
  GlBuffer volumes[2] = {GlBuffer(gl, createBuffer(gl, bytes, words.data())),
                         GlBuffer(gl, createBuffer(gl, bytes, nullptr))};
  if (s.accumulateInjection == LpvToggle::off) std::fill(words.begin(), words.end(), 0u);
  GlBuffer accumulated(gl, createBuffer(gl, bytes, words.data()));
  const Buffer* blocking = buffers.find(BufferId::lpv_inject_geometry_blocking);
  GlBuffer blockingBlock(
      gl, blocking != nullptr ? uploadWords(gl, *blocking) : createBuffer(gl, 16, nullptr));
  const uint64_t historyBytes = uint64_t(bytes) * uint64_t(setup.steps + 1);
  GlBuffer steps(gl, history ? createBuffer(gl, historyBytes, nullptr) : 0u);
  if (history) gl.CopyNamedBufferSubData(volumes[0].get(), steps.get(), 0, 0, GLsizeiptr(bytes));

  Program program(gl, {&shaders::lpv_propagate_comp});
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, entryBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, accumulated.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, blockingBlock.get());
  const auto groups = static_cast<GLuint>((n + 3) / 4);
  for (int step = 1; step <= setup.steps; ++step) {
    const bool occlude = voxgi::lpv::occludedStep(s, step);
    if (occlude && blocking == nullptr)
      throw std::logic_error("propagate: occlusion without inject_geometry's blocking volume");
    program.set("uOcclude", occlude ? 1 : 0);
    GlBuffer& from = volumes[(step - 1) % 2];
    GlBuffer& to = volumes[step % 2];
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, from.get());
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, to.get());
    gl.DispatchCompute(groups, groups, groups);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (history)
      gl.CopyNamedBufferSubData(to.get(), steps.get(), 0, GLintptr(uint64_t(step) * bytes),
                                GLsizeiptr(bytes));
    gl.check("propagate: dispatch");
  }
  // Reads `volumeCount` volumes of `from` into `out` as f32 words.
  const auto readVolumes = [&](GLuint from, Buffer& out, size_t volumeCount) {
    if (!packed) return readWords(gl, from, out);
    std::vector<uint32_t> all(words.size() * volumeCount);
    gl.GetNamedBufferSubData(from, 0, GLsizeiptr(all.size() * 4), all.data());
    voxgi::lpv::unpackStoredVolume(all.data(), cells * volumeCount, values, setup.params,
                                   out.words.data());
  };
  Buffer out(sh.accumulated, glm::ivec3(n));
  readVolumes(accumulated.get(), out, 1);
  buffers.put(std::move(out));
  if (history) {
    Buffer all(sh.steps, glm::ivec3(n, n, n * (setup.steps + 1)));
    readVolumes(steps.get(), all, size_t(setup.steps) + 1);
    buffers.put(std::move(all));
  }
  gl.check("propagate: reading back");
}

}  // namespace voxgi::gpu
