// Building a radiance pyramid texture with shaders/vct/mip.comp, for the mip stage and for bounce,
// which rebuilds it after every bounce without leaving the GPU.
#pragma once

#include "gpu/gl.h"

namespace voxgi::gpu {

// A pyramid texture (gpu/volumes.h createPyramid layout) of the N^3 RGBA32F `radiance` texture,
// with `faces` faces (1: isotropic, 6: directional). N must be at least 2.
GlTexture buildPyramid(const Gl& gl, GLuint radiance, int n, int faces);

}  // namespace voxgi::gpu
