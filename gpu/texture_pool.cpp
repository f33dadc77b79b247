#include "gpu/texture_pool.h"

namespace voxgi::gpu {

TexturePoolBuffers::TexturePoolBuffers(const Gl& gl, const TexturePool& pool)
    : texels_(gl, createBuffer(gl, pool.texels.size() * sizeof(uint32_t), pool.texels.data())),
      records_(gl, createBuffer(gl, pool.textures.size() * sizeof(shared::TextureRecord),
                                pool.textures.data())),
      srgb_(gl,
            createBuffer(gl, sizeof(float) * srgbDecodeTable().size(), srgbDecodeTable().data())) {
  bind(gl);
}

void TexturePoolBuffers::bind(const Gl& gl) const {
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, texels_.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, records_.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, srgb_.get());
}

}  // namespace voxgi::gpu
