// The texture pool of a scene (common/texture.h) as storage buffers, and the accessors
// shaders/shared/texture_kernel.h reads it through (FETCH). Include after shared/texture_layout.h
// and before the kernel; gpu/texture_pool.cpp binds the buffers.
layout(std430, binding = 5) readonly buffer TextureTexels { uint textureTexels[]; };
layout(std430, binding = 6) readonly buffer TextureRecords { TextureRecord textureRecords[]; };
layout(std430, binding = 7) readonly buffer SrgbTable { float srgbTable[]; };

uint textureWord(uint i) { return textureTexels[i]; }
float srgbDecode(uint code) { return srgbTable[code]; }
TextureRecord textureRecord(uint i) { return textureRecords[i]; }
