#include "gpu/volumes.h"

#include <stdexcept>
#include <string>

#include "common/error.h"
#include "common/mips.h"

namespace voxgi::gpu {
namespace {

void checkComponents(int components) {
  if (components < 1 || components > 4)
    throw std::logic_error("a texture holds 1 to 4 components, not " + std::to_string(components) +
                           ": use uploadWords (gpu/volumes.h)");
}

GLenum pixelFormat(int components) {
  checkComponents(components);
  constexpr GLenum formats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  return formats[components - 1];
}

}  // namespace

const Gl& beginStage(GlContext& context, const StageContext& ctx, StageId stage) {
  context.makeCurrent();
  checkStageMemory(ctx, stage, 2.0);
  return context.gl();
}

GLenum floatFormat(int components) {
  checkComponents(components);
  constexpr GLenum formats[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
  return formats[components - 1];
}

GLuint createTexture3d(const Gl& gl, GLenum internalFormat, glm::ivec3 size, int levels) {
  GLuint texture = 0;
  gl.CreateTextures(GL_TEXTURE_3D, 1, &texture);
  gl.TextureStorage3D(texture, levels, internalFormat, size.x, size.y, size.z);
  return texture;
}

GLuint createVolume(const Gl& gl, int components, glm::ivec3 size, int levels) {
  return createTexture3d(gl, floatFormat(components), size, levels);
}

GLuint uploadWords(const Gl& gl, const Buffer& b) {
  return createBuffer(gl, b.words.size() * 4, b.words.data());
}

GLuint uploadVolume(const Gl& gl, const Buffer& b) {
  const GLuint texture = createVolume(gl, b.components(), b.extent);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.TextureSubImage3D(texture, 0, 0, 0, 0, b.extent.x, b.extent.y, b.extent.z,
                       pixelFormat(b.components()), GL_FLOAT, b.words.data());
  return texture;
}

void readWords(const Gl& gl, GLuint buffer, Buffer& out, size_t offset) {
  gl.GetNamedBufferSubData(buffer, GLintptr(offset), GLsizeiptr(out.words.size() * 4),
                           out.words.data());
}

void requireStorageBlock(const Gl& gl, const StageContext& ctx, uint64_t bytes,
                         const std::string& what) {
  GLint64 limit = 0;
  gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  if (bytes <= uint64_t(limit)) return;
  throw InputError(ctx.scene.file, "grid.resolution",
                   what + " take " + std::to_string(bytes >> 20) + " MiB, more than this GL's " +
                       std::to_string(uint64_t(limit) >> 20) +
                       " MiB shader storage block limit; lower the resolution or use --backend "
                       "cpu");
}

void readTexture(const Gl& gl, GLuint texture, int level, GLenum format, GLenum type,
                 glm::ivec3 size, Buffer& out, size_t offset) {
  gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
  const size_t first = offset * size_t(out.components());
  const size_t channels = format == GL_RG ? 2 : format == GL_RGB ? 3 : format == GL_RGBA ? 4 : 1;
  const size_t words = size_t(size.x) * size_t(size.y) * size_t(size.z) * channels;
  if (first + words > out.words.size())
    throw std::logic_error("readTexture: the texture does not fit the buffer " +
                           out.spec->qualifiedName());
  gl.GetTextureImage(texture, level, format, type, static_cast<GLsizei>(words * 4),
                     out.words.data() + first);
}

void readVolume(const Gl& gl, GLuint texture, int level, glm::ivec3 size, Buffer& out,
                size_t offset) {
  readTexture(gl, texture, level, pixelFormat(out.components()), GL_FLOAT, size, out, offset);
}

GLuint createPyramid(const Gl& gl, int resolution, int faces) {
  const int half = resolution / 2;
  return createVolume(gl, 4, {faces * half, half, half}, mipLevelCount(resolution));
}

GLuint uploadPyramid(const Gl& gl, const Buffer& b, int resolution, int faces) {
  const GLuint texture = createPyramid(gl, resolution, faces);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int level = 1; level <= mipLevelCount(resolution); ++level) {
    const int s = resolution >> level;
    gl.TextureSubImage3D(texture, level - 1, 0, 0, 0, faces * s, s, s, GL_RGBA, GL_FLOAT,
                         b.words.data() + 4 * mipLevelOffset(resolution, level, faces));
  }
  return texture;
}

Buffer readPyramid(const Gl& gl, GLuint texture, const BufferSpec& spec, int resolution,
                   int faces) {
  Buffer out(spec, shapeExtent(spec.shape, resolution, {}));
  for (int level = 1; level <= mipLevelCount(resolution); ++level) {
    const int s = resolution >> level;
    readVolume(gl, texture, level - 1, {faces * s, s, s}, out,
               mipLevelOffset(resolution, level, faces));
  }
  return out;
}

}  // namespace voxgi::gpu
