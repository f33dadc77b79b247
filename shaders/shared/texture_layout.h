// A texture as the kernels see it (std430), shared by C++ and GLSL: what common/texture.h's pool
// stores per texture and shaders/texture_access.glsl binds (docs/textures.md).
#ifndef VOXGI_TEXTURE_LAYOUT_H
#define VOXGI_TEXTURE_LAYOUT_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// glTF's sampler wrap modes (its numbers are 10497, 33071 and 33648).
const uint kWrapRepeat = 0u;
const uint kWrapClamp = 1u;
const uint kWrapMirror = 2u;

// No texture: a material slot that holds this reads its constant factor alone.
const uint kNoTexture = 0xffffffffu;

// One texture as the kernels see it (std430, 32 bytes): its image's levels in the texel pool (level
// 0 at `offset`, each level after the one before, max(1, size >> l) per side) and its sampler.
struct TextureRecord {
  uint offset;
  int width;
  int height;
  int levels;
  uint wrapS;
  uint wrapT;
  uint pad0;
  uint pad1;
};

VOXGI_NAMESPACE_END
#endif
