// One GL context per platform for the whole test binary (creating contexts is slow), and the
// diff of vct stages on one.
#pragma once

#include <string>
#include <vector>

#include "common/scene.h"
#include "common/settings.h"
#include "gpu/context.h"
#include "validation/diff.h"

namespace voxgi::test {

// The shared context of `platform`; fails the calling test (via exception) if none can be made:
// CI always has OSMesa and EGL surfaceless, so a missing context is a real failure.
gpu::GlContext& glContext(gpu::GlPlatform platform);

// `voxgi diff` of vct's stages named in `stages` (each resolved as --stage is), CPU against the
// GPU backend on `context`.
std::vector<validation::StageReport> diffVct(const Scene& scene, const Settings& settings,
                                             gpu::GlContext& context,
                                             const std::vector<std::string>& stages);
// The same for any technique.
std::vector<validation::StageReport> diffTechnique(const Technique& technique, const Scene& scene,
                                                   const Settings& settings,
                                                   gpu::GlContext& context,
                                                   const std::vector<std::string>& stages);

}  // namespace voxgi::test
