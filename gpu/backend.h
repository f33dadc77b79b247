// The OpenGL backend for the stage runner (common/pipeline.h), on one context.
#pragma once

#include "common/pipeline.h"
#include "gpu/context.h"

namespace voxgi::gpu {

class GpuBackend : public StageBackend {
 public:
  explicit GpuBackend(GlContext& context) : context_(context) {}
  std::string name() const override { return "gpu: " + context_.renderer(); }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override;

 private:
  GlContext& context_;
};

}  // namespace voxgi::gpu
