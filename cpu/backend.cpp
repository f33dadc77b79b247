#include "cpu/backend.h"

#include "cpu/stages.h"

namespace voxgi::cpu {

void CpuBackend::run(StageId stage, const StageContext& ctx, BufferSet& buffers) {
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary) &owner::stage,
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
  static constexpr void (*table[])(const StageContext&, BufferSet&) = {
#include "common/stages.inc"
  };
  table[static_cast<size_t>(stage)](ctx, buffers);
}

}  // namespace voxgi::cpu
