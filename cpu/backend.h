// The CPU backend for the stage runner (common/pipeline.h).
#pragma once

#include "common/pipeline.h"

namespace voxgi::cpu {

class CpuBackend : public StageBackend {
 public:
  std::string name() const override { return "cpu"; }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override;
};

}  // namespace voxgi::cpu
