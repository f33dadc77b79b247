#include "validation/stage_functions.h"

#include "cpu/stages.h"
#include "gpu/stages.h"

namespace voxgi::validation {

std::span<const StageFunctions> stageFunctions() {
#define VOXGI_STAGE(stage, summary) StageFunctions{#stage, &cpu::stage, &gpu::stage},
  static const StageFunctions table[] = {
#include "common/stages.inc"
  };
#undef VOXGI_STAGE
  return table;
}

}  // namespace voxgi::validation
