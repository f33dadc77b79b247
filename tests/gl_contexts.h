// One GL context per platform for the whole test binary (creating contexts is slow).
#pragma once

#include "gpu/context.h"

namespace voxgi::test {

// The shared context of `platform`; fails the calling test (via exception) if none can be made:
// CI always has OSMesa and EGL surfaceless, so a missing context is a real failure.
gpu::GlContext& glContext(gpu::GlPlatform platform);

}  // namespace voxgi::test
