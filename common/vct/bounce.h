// bounce's host preparation: the cone kernels' parameters without lights
// (common/vct/trace_cones.h).
#pragma once

#include "common/vct/trace_cones.h"

namespace voxgi {

// The same for the bounce stage: the diffuse cone set only (no lights, objects or ambient
// occlusion).
ConeTraceSetup prepareBounce(const StageContext& ctx);

}  // namespace voxgi
