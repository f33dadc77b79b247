// Moving stage buffers in and out of GL textures. Every buffer keeps the CPU layout
// (common/buffer.h): a volume is one 3D texture, a pyramid (mips, mips6) one mipmapped 3D texture
// whose level l-1 holds pyramid level l, an image a 2D texture. Shaders read with texelFetch and
// write with imageStore, so values pass through unchanged.
#pragma once

#include "common/buffer.h"
#include "common/stage.h"
#include "gpu/context.h"
#include "gpu/gl.h"

namespace voxgi::gpu {

// Makes the context current and checks memory for the stage's buffers twice over (GL copies plus
// the read-back); returns the function table.
const Gl& beginStage(GlContext& context, const StageContext& ctx, std::string_view stage);

// Float internal format for 1, 2, 3 or 4 components (R32F ... RGBA32F).
GLenum floatFormat(int components);

// An immutable 3D float texture of `size` with `levels` mip levels.
GLuint createVolume(const Gl& gl, int components, glm::ivec3 size, int levels = 1);
// A 3D texture holding the volume buffer `b` (any extent).
GLuint uploadVolume(const Gl& gl, const Buffer& b);
// Reads `level` of a 3D float texture into `out` starting at element `offset`.
void readVolume(const Gl& gl, GLuint texture, int level, glm::ivec3 size, Buffer& out,
                size_t offset = 0);

// A pyramid texture for an N^3 volume: levels 1..log2(N) at texture levels 0.., `faces` volumes
// side by side along x.
GLuint createPyramid(const Gl& gl, int resolution, int faces);
// A pyramid texture holding the pyramid buffer `b` (shape mips or mips6).
GLuint uploadPyramid(const Gl& gl, const Buffer& b, int resolution, int faces);
Buffer readPyramid(const Gl& gl, GLuint texture, const BufferSpec& spec, int resolution, int faces);

}  // namespace voxgi::gpu
