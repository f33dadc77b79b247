// The sparse voxel octree's build on the GPU (shaders/svo/build.comp): the structure
// allocated with atomics level by level, pools grown to the tiles actually allocated, the leaf
// sums with integer atomics; read back in the canonical form (common/svo/canonical.h), which
// equals the CPU build's (cpu/svo/octree.h) word for word.
#pragma once

#include <span>
#include <string>

#include "common/svo/canonical.h"
#include "gpu/context.h"
#include "shaders/shared/svo/build_kernel.h"

namespace voxgi::gpu::svo {

// Throws InputError naming `source` and grid.resolution when a leaf's opacity passes 2^31 - 1
// units or the counted tiles would not fit in memory.
voxgi::svo::OctreeWords buildOctree(GlContext& context, std::span<const shared::SvoSample> samples,
                                    int depth, float scale, const std::string& source);

}  // namespace voxgi::gpu::svo
