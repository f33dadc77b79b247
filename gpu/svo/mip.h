// svo's mip on the GPU (shaders/svo/mip.comp): the six faces of every node from the leaves'
// radiance up to the root tile; svo's propagate mips every frame's light with it too. The twin of
// cpu/svo/mip.h; on llvmpipe it equals the CPU's bit for bit.
#pragma once

#include "gpu/svo/svo_volumes.h"

namespace voxgi::gpu::svo {

voxgi::svo::NodeLevels mipTree(GlContext& context, const Tree& tree,
                               const voxgi::svo::Leaves& leaves,
                               const voxgi::svo::LeafRadiance& radiance,
                               voxgi::svo::FirstStep first);

// Fills v.nodeFaces from `first`'s leaves up to the root tile; returns them per level.
voxgi::svo::NodeLevels mipInto(const Gl& gl, const Tree& t, const SvoVolumes& v,
                               voxgi::svo::FirstStep first);

}  // namespace voxgi::gpu::svo
