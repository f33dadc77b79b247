// Diffuse cones at a reduced resolution (cones.diffuse_scale = s > 1), shared by
// cpu/vct/trace_cones.cpp and shaders/vct/trace_cones.comp. The diffuse cone set is
// traced once per s x s block of pixels, from one of the block's surface pixels (the block's
// sample); every pixel then blends the samples of the 2 x 2 blocks around it, each weighted
// bilinearly and by how well the sample's surface stands for the pixel's (normals alike, the
// sample on the pixel's tangent plane): joint bilateral upsampling [Kopf et al. 2007]. A pixel
// that no sample stands for (an edge, a thin object) traces its own cones, so indirect light is
// never carried across a silhouette or a crease.
#ifndef VOXGI_DIFFUSE_UPSAMPLE_H
#define VOXGI_DIFFUSE_UPSAMPLE_H
#include "diffuse_samples.h"

VOXGI_NAMESPACE_BEGIN

// Farther than this (voxels) from a pixel's tangent plane, a sample stands for none of it: the
// sample lies on another surface (a step, a box in front of a wall), whose light differs.
const float kUpsamplePlane = 1.0f;
// A pixel blends its samples only if one of them matches at least this well (sampleMatch): cos^8
// is 1/2 at 23 degrees between the normals.
const float kUpsampleMatch = 0.5f;

// How well sample s stands for the pixel at p with unit normal n, in [0, 1]: cos^8 of the angle
// between the normals, times 1 - (the sample's distance to the pixel's tangent plane) /
// kUpsamplePlane. Exact operations only, so both backends make the same choices.
VOXGI_FN float sampleMatch(vec3 p, vec3 n, DiffuseSample s) {
  precise float facing = max(dot3(n, vec3(s.normal)), 0.0f);
  precise float f2 = facing * facing;
  precise float f4 = f2 * f2;
  precise float off = abs(dot3(n, vec3(s.position) - p));
  precise float near = max(1.0f - off / kUpsamplePlane, 0.0f);
  precise float match = s.position.w * (f4 * f4) * near;
  return match;
}

// The first of the 2 x 2 blocks around pixel px (it may lie outside the image's blocks) and px's
// bilinear position between their centres, in [0, 1).
VOXGI_FN ivec2 upsampleCorner(ivec2 px, int scale, OUT(vec2) t) {
  precise vec2 at = (vec2(px) + 0.5f) / float(scale) - 0.5f;
  vec2 corner = floor(at);
  t = at - corner;
  return ivec2(corner);
}

// The bilinear weight of the corner's block (dx, dy) (0 or 1 each).
VOXGI_FN float cornerWeight(vec2 t, int dx, int dy) {
  precise float wx = dx == 1 ? t.x : 1.0f - t.x;
  precise float wy = dy == 1 ? t.y : 1.0f - t.y;
  precise float w = wx * wy;
  return w;
}

// The samples of a pixel blended so far: weighted sums, the weights' sum, the best match.
struct DiffuseBlend {
  vec3 radiance;
  float ambient;
  float weights;
  float total;
  float best;
};

VOXGI_FN DiffuseBlend noBlend() {
  DiffuseBlend b;
  b.radiance = vec3(0.0f);
  b.ambient = 0.0f;
  b.weights = 0.0f;
  b.total = 0.0f;
  b.best = 0.0f;
  return b;
}

// b plus sample s at bilinear weight `bilinear`, for the pixel at p with normal n. The four
// corners are added in the order (0, 0), (1, 0), (0, 1), (1, 1).
VOXGI_FN DiffuseBlend blendSample(DiffuseBlend b, DiffuseSample s, float bilinear, vec3 p, vec3 n) {
  float match = sampleMatch(p, n, s);
  precise float w = bilinear * match;
  precise vec3 radiance = b.radiance + vec3(s.radiance) * w;
  precise float ambient = b.ambient + s.sums.x * w;
  precise float weights = b.weights + s.sums.y * w;
  precise float total = b.total + w;
  b.radiance = radiance;
  b.ambient = ambient;
  b.weights = weights;
  b.total = total;
  // A sample at bilinear weight 0 (a pixel on a block's centre line at odd scales) stands for
  // nothing: the blend's weights must not all be 0.
  b.best = bilinear > 0.0f ? max(b.best, match) : b.best;
  return b;
}

// Whether the blend stands for the pixel; if not, the pixel traces its own diffuse cones.
VOXGI_FN bool blendFound(DiffuseBlend b) {
  return b.best >= kUpsampleMatch;
}

// The pixel's diffuse sum from a found blend: the samples' weighted mean.
VOXGI_FN DiffuseSum blendedDiffuse(DiffuseBlend b) {
  DiffuseSum s;
  precise vec3 radiance = b.radiance / b.total;
  precise float ambient = b.ambient / b.total;
  precise float weights = b.weights / b.total;
  s.radiance = radiance;
  s.ambient = ambient;
  s.weights = weights;
  return s;
}

// The blend of the samples of the 2 x 2 blocks around pixel px (at p, unit normal n), read with
// FETCH(diffuseSampleAt)(block), which gives noDiffuseSample() outside the image's blocks.
VOLUME_FN DiffuseBlend blendAround(VOLUMES_IN ivec2 px, vec3 p, vec3 n, int scale) {
  vec2 t;
  ivec2 corner = upsampleCorner(px, scale, t);
  DiffuseBlend b = noBlend();
  for (int k = 0; k < 4; ++k) {
    int dx = k & 1;
    int dy = k >> 1;
    b = blendSample(b, FETCH(diffuseSampleAt)(corner + ivec2(dx, dy)), cornerWeight(t, dx, dy), p,
                    n);
  }
  return b;
}

// The diffuse sum of pixel px at p with unit normal n: its own cones at cones.diffuse_scale 1,
// else its samples' blend, or its own cones where no sample stands for it. FETCH reads both the
// blocks' samples and the cone tracer's volumes.
VOLUME_FN DiffuseSum pixelDiffuse(VOLUMES_IN ivec2 px, vec3 p, vec3 n, ConeTraceParams params) {
  if (params.diffuseScale > 1) {
    DiffuseBlend b = blendAround(VOLUMES px, p, n, params.diffuseScale);
    if (blendFound(b)) return blendedDiffuse(b);
  }
  return traceDiffuse(VOLUMES p, n, params);
}

VOXGI_NAMESPACE_END
#endif
