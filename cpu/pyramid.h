// Building a radiance pyramid on the CPU (cpu/mip.cpp), for the mip stage and for bounce, which
// rebuilds it after every bounce.
#pragma once

#include "common/buffer.h"

namespace voxgi::cpu {

// Every level of the pyramid of the N^3 `radiance` volume with `faces` faces (1: isotropic, 6:
// directional), as a buffer of `spec` (shape mips or mips6).
Buffer buildPyramid(const BufferSpec& spec, const Buffer& radiance, int n, int faces);

}  // namespace voxgi::cpu
