// Moving stage buffers in and out of GL. Every buffer keeps the CPU layout (common/buffer.h): a
// volume of 1 to 4 components is one 3D texture, a pyramid (mips, mips6) one mipmapped 3D texture
// whose level l-1 holds pyramid level l; a buffer of more components (3-band RGB SH: 27) or any
// buffer a shader indexes by element is a shader storage buffer of its words. Shaders read with
// texelFetch (or index the words) and write with imageStore, so values pass through unchanged.
// Integer sums that shaders accumulate with image atomics use single-channel 3N x N x N textures
// (texel (3i + c, j, k)), which is the same layout.
#pragma once

#include "common/buffer.h"
#include "common/stage.h"
#include "gpu/context.h"
#include "gpu/gl.h"

namespace voxgi::gpu {

// Makes the context current and checks memory for the stage's buffers twice over (GL copies plus
// the read-back); returns the function table.
const Gl& beginStage(GlContext& context, const StageContext& ctx, StageId stage);

// Float internal format for 1, 2, 3 or 4 components (R32F ... RGBA32F); throws std::logic_error
// for any other count (such a buffer goes to uploadWords).
GLenum floatFormat(int components);

// An immutable 3D texture of `internalFormat` and `size` with `levels` mip levels.
GLuint createTexture3d(const Gl& gl, GLenum internalFormat, glm::ivec3 size, int levels = 1);
// An immutable 3D float texture of `components` (1 to 4), `size` and `levels` mip levels.
GLuint createVolume(const Gl& gl, int components, glm::ivec3 size, int levels = 1);
// A 3D texture holding the volume buffer `b` (any extent, 1 to 4 components).
GLuint uploadVolume(const Gl& gl, const Buffer& b);
// A shader storage buffer holding the words of `b` as they are (any shape and component count).
GLuint uploadWords(const Gl& gl, const Buffer& b);
// Reads out's words from the buffer object `buffer`, starting at byte `offset`.
void readWords(const Gl& gl, GLuint buffer, Buffer& out, size_t offset = 0);
// Throws InputError naming the scene's grid.resolution when one shader storage block of `bytes`
// exceeds GL_MAX_SHADER_STORAGE_BLOCK_SIZE (llvmpipe: 128 MiB), so a stage fails before it
// dispatches instead of reading out of range.
void requireStorageBlock(const Gl& gl, const StageContext& ctx, uint64_t bytes,
                         const std::string& what);
// Reads `level` (of `size` texels) of a 3D texture as `format`/`type` (GL_RED_INTEGER and
// GL_UNSIGNED_INT, ...) into out's words from element `offset` on; throws std::logic_error if they
// do not fit.
void readTexture(const Gl& gl, GLuint texture, int level, GLenum format, GLenum type,
                 glm::ivec3 size, Buffer& out, size_t offset = 0);
// Reads `level` of a 3D float texture of out's component count into `out` from element `offset`.
void readVolume(const Gl& gl, GLuint texture, int level, glm::ivec3 size, Buffer& out,
                size_t offset = 0);

// A pyramid texture for an N^3 volume: levels 1..log2(N) at texture levels 0.., `faces` volumes
// side by side along x.
GLuint createPyramid(const Gl& gl, int resolution, int faces);
// A pyramid texture holding the pyramid buffer `b` (shape mips or mips6).
GLuint uploadPyramid(const Gl& gl, const Buffer& b, int resolution, int faces);
Buffer readPyramid(const Gl& gl, GLuint texture, const BufferSpec& spec, int resolution, int faces);

}  // namespace voxgi::gpu
