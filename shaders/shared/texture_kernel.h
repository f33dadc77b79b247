// Texture sampling shared by every stage that reads a material's texture (voxelize, gbuffer, the
// reflective shadow maps, the octree's surface samples) and the path tracer: wrap, bilinear
// filtering in linear space and a blend between two mip levels, from texels stored as 8-bit sRGB.
// One order of operations on both backends, so the CPU/GPU diffs stay exact (docs/textures.md).
//
// Reads through the accessor of glsl_cpp.h (VOLUME_FN): FETCH(textureWord)(i) is texel word i of
// the pool every image's levels are packed in (RGBA8, r in the low byte), FETCH(srgbDecode)(code)
// the linear value of an 8-bit sRGB code (a table made on the host: common/texture.cpp) and
// FETCH(textureRecord)(i) texture i; shaders define them in shaders/texture_access.glsl.
#ifndef VOXGI_TEXTURE_KERNEL_H
#define VOXGI_TEXTURE_KERNEL_H
#include "approx_math.h"
#include "glsl_cpp.h"
#include "texture_layout.h"

VOXGI_NAMESPACE_BEGIN

// A texture coordinate brought into the period of its wrap mode, where floor() and int() cannot
// overflow: [0, 1) for repeat, [0, 2) for mirror, [0, 1] for clamp.
VOXGI_FN float wrapCoordinate(float u, uint mode) {
  if (mode == kWrapClamp) return clamp(u, 0.0f, 1.0f);
  if (mode == kWrapMirror) {
    precise float r = u - 2.0f * floor(u * 0.5f);
    return min(r, 1.99999988f);  // u - 2 floor(u/2) can round up to 2
  }
  precise float r = u - floor(u);
  return min(r, 0.99999994f);
}

// The texel a (possibly out-of-range) integer coordinate reads in a level of n texels.
VOXGI_FN int wrapTexel(int i, int n, uint mode) {
  if (mode == kWrapClamp) return clamp(i, 0, n - 1);
  if (mode == kWrapMirror) {
    int m = ((i % (2 * n)) + 2 * n) % (2 * n);
    return m < n ? m : 2 * n - 1 - m;
  }
  return ((i % n) + n) % n;
}

// One texel of a level, decoded to linear RGB.
VOLUME_FN vec3 textureTexel(VOLUMES_IN uint levelOffset, int width, int x, int y) {
  uint word = FETCH(textureWord)(levelOffset + uint(y) * uint(width) + uint(x));
  return vec3(FETCH(srgbDecode)(word & 255u), FETCH(srgbDecode)((word >> 8u) & 255u),
              FETCH(srgbDecode)((word >> 16u) & 255u));
}

VOXGI_FN vec3 lerpTexel(vec3 a, vec3 b, float t) {
  precise vec3 r = a + (b - a) * t;  // a constant stays itself bit for bit
  return r;
}

// Bilinear filtering of one level at a wrapped coordinate (texel centres at (i + 1/2) / size).
VOLUME_FN vec3 bilinearLevel(VOLUMES_IN TextureRecord t, int level, vec2 uv) {
  uint offset = t.offset;
  int w = t.width;
  int h = t.height;
  for (int l = 0; l < level; ++l) {
    offset = offset + uint(w) * uint(h);
    w = max(1, w / 2);
    h = max(1, h / 2);
  }
  precise float x = wrapCoordinate(uv.x, t.wrapS) * float(w) - 0.5f;
  precise float y = wrapCoordinate(uv.y, t.wrapT) * float(h) - 0.5f;
  precise float x0 = floor(x);
  precise float y0 = floor(y);
  precise float fx = x - x0;
  precise float fy = y - y0;
  int i0 = wrapTexel(int(x0), w, t.wrapS);
  int i1 = wrapTexel(int(x0) + 1, w, t.wrapS);
  int j0 = wrapTexel(int(y0), h, t.wrapT);
  int j1 = wrapTexel(int(y0) + 1, h, t.wrapT);
  vec3 bottom = lerpTexel(textureTexel(VOLUMES offset, w, i0, j0),
                          textureTexel(VOLUMES offset, w, i1, j0), fx);
  vec3 top = lerpTexel(textureTexel(VOLUMES offset, w, i0, j1),
                       textureTexel(VOLUMES offset, w, i1, j1), fx);
  return lerpTexel(bottom, top, fy);
}

// The mip level (fractional) for a filter `footprint` wide in texture coordinates (a length in
// uv units: sqrt of the uv area it covers): log2 of its width in level-0 texels (a non-square
// texture counts sqrt(width * height) texels per unit), clamped to the texture's levels; 0
// magnifies. log2Approx is exact-rounded arithmetic, so both backends pick the same levels.
VOXGI_FN float textureLod(TextureRecord t, float footprint) {
  precise float texels = footprint * sqrt(float(t.width) * float(t.height));
  if (!(texels > 1.0f)) return 0.0f;
  return clamp(log2Approx(texels), 0.0f, float(t.levels - 1));
}

// The texture at uv, filtered over `lod` (textureLod): bilinear in the two nearest levels, blended
// linearly between them (trilinear filtering).
VOLUME_FN vec3 sampleTexture(VOLUMES_IN TextureRecord t, vec2 uv, float lod) {
  precise float level = floor(lod);
  precise float f = lod - level;
  vec3 a = bilinearLevel(VOLUMES t, int(level), uv);
  if (f == 0.0f) return a;
  vec3 b = bilinearLevel(VOLUMES t, int(level) + 1, uv);
  return lerpTexel(a, b, f);
}

// A material's value: its constant factor, times its texture at uv when it has one.
VOLUME_FN vec3 texturedValue(VOLUMES_IN vec3 factor, uint texture, vec2 uv, float footprint) {
  if (texture == kNoTexture) return factor;
  TextureRecord t = FETCH(textureRecord)(texture);
  precise vec3 r = factor * sampleTexture(VOLUMES t, uv, textureLod(t, footprint));
  return r;
}

VOXGI_NAMESPACE_END
#endif
