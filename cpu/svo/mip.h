// svo's mip: the six faces of every node from the leaves' radiance up to the root tile, with the
// cone library's anisotropic mip (shaders/shared/cone/mip.h); svo's propagate mips every frame's
// light with it too. The twin of gpu/svo/mip.h.
#pragma once

#include "cpu/svo/svo_volumes.h"

namespace voxgi::cpu::svo {

// The six faces of every node, from the leaves' radiance up to the root tile.
NodeLevels mipTree(const Octree& octree, const Leaves& leaves, const LeafRadiance& radiance,
                   FirstStep first);

}  // namespace voxgi::cpu::svo
