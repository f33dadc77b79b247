// A scene's texture pool (common/texture.h) on the GPU: its texels, its texture records and the
// sRGB table as the storage buffers shaders/texture_access.glsl reads (bindings 5-7), so the
// shaders sample the same words as the CPU.
#pragma once

#include "common/texture.h"
#include "gpu/gl.h"

namespace voxgi::gpu {

class TexturePoolBuffers {
 public:
  // Uploads the pool and binds it; an empty pool gets one-word buffers, which nothing reads.
  TexturePoolBuffers(const Gl& gl, const TexturePool& pool);
  void bind(const Gl& gl) const;

 private:
  GlBuffer texels_, records_, srgb_;
};

}  // namespace voxgi::gpu
