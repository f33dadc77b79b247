// Building a radiance pyramid on the CPU, for the mip stage and for bounce, which rebuilds it
// after every bounce.
#pragma once

#include "common/buffer.h"

namespace voxgi::cpu {

// Every level of the pyramid of the N^3 `radiance` volume into `out`, a buffer of `spec`: shape
// mips (isotropic) or mips6 (six directional faces). An `out` that already has
// that spec and size is overwritten in place: a pyramid rebuilt every frame or bounce keeps its
// memory instead of faulting in fresh pages each time.
void buildPyramid(const BufferSpec& spec, const Buffer& radiance, int n, Buffer& out);

}  // namespace voxgi::cpu
