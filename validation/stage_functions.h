// The stage graph of common/stages.inc as a table of both backends' functions, in graph order,
// for everything that runs stages by name (diff, dump, benchmarks, tests).
#pragma once

#include <span>
#include <string_view>

#include "common/stage.h"
#include "gpu/context.h"

namespace voxgi::validation {

struct StageFunctions {
  std::string_view name;
  void (*cpu)(const StageContext&, BufferSet&);
  void (*gpu)(gpu::GlContext&, const StageContext&, BufferSet&);
};

std::span<const StageFunctions> stageFunctions();

}  // namespace voxgi::validation
