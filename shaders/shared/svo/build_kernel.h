// Region-of-influence splatting of scene samples into the octree's leaves [Salm 2015, §4.3.4],
// shared by build on both backends. A sample's RoI is an axis-aligned cube of edge r <= 1 leaf
// cell about its position; it adds to each leaf its opacity density times the volume the cube
// shares with the leaf's cell (at most 2 cells per axis, 8 leaves; for r = 1 the trilinear tent
// weights), and the premultiplied albedo, normal and emission in the same proportion. Sums are in
// fixed point, so the order of the additions cannot change them. Included by C++ and GLSL.
#ifndef VOXGI_SVO_SPLAT_KERNEL_H
#define VOXGI_SVO_SPLAT_KERNEL_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// One scene sample prepared for the build (common/svo/samples.cpp), 64 bytes, std430; in C++ on a
// cache line of its own, as the CPU build reads samples in an order of their own (a sample across
// two lines cost two misses).
#ifdef __cplusplus
struct alignas(64) SvoSample {
#else
struct SvoSample {
#endif
  vec3 position;  // leaf voxel units (leaf (i,j,k) covers [i,i+1) x ...)
  float edge;     // the edge r of the sample's region of influence (RoI), in (0, 1]
  vec3 albedo;    // in [0, 1]
  float density;  // opacity density (1 / r: a surface's samples sum to 1)
  vec3 normal;    // unit surface normal
  float pad0;
  vec3 emission;  // emission / the build's emission scale, in [0, 1]
  float pad1;
};

// Fixed point: a leaf's sums count units of 1/scale of opacity x cell volume, with a power-of-two
// scale the host chooses for the samples (common/svo/samples.h) so that no leaf's sum can pass
// 2^31 - 1; both backends still check the opacity sum, which bounds every other sum's magnitude
// (|albedo|, |normal| and the scaled emission are at most 1).

// Leaf sums per leaf voxel, in this order (`leaf_sums`, 8 voxels a leaf tile by local id).
const int kSumOpacity = 0;   // units of opacity x volume
const int kSumAlbedo = 1;    // 1..3: sum of round(weight x albedo)
const int kSumNormal = 4;    // 4..6: signed, round(weight x normal)
const int kSumEmission = 7;  // 7..9: round(weight x scaled emission)
const int kSumWords = 10;

// The RoI [p - r/2, p + r/2] on one axis against cells lo and lo + 1: the lengths it covers.
struct SplatAxis {
  int lo;
  float w0;
  float w1;
};

VOXGI_FN SplatAxis splatAxis(float p, float r) {
  SplatAxis s;
  precise float a = p - 0.5f * r;
  precise float b = p + 0.5f * r;
  precise float lo = floor(a);
  precise float mid = lo + 1.0f;
  precise float w0 = min(b, mid) - a;
  precise float w1 = max(b - mid, 0.0f);
  s.lo = int(lo);
  s.w0 = w0;
  s.w1 = w1;
  return s;
}

// The weight (opacity density x shared volume) corner c (0 or 1 per axis) of the sample's 2x2x2
// leaf block receives.
VOXGI_FN float splatWeight(SplatAxis x, SplatAxis y, SplatAxis z, float density, ivec3 c) {
  precise float wx = c.x == 0 ? x.w0 : x.w1;
  precise float wy = c.y == 0 ? y.w0 : y.w1;
  precise float wz = c.z == 0 ? z.w0 : z.w1;
  precise float w = ((wx * wy) * wz) * density;
  return w;
}

// round(weight x value x scale), |weight x scale| below 2^30 (the host's scale guarantees it).
// floor is exact on both backends; in C++ it is written with a truncating conversion, which is
// exact too and avoids a libm call per value (the CPU build rounds 10^8 of them).
VOXGI_FN int fixedRound(float weight, float value, float scale) {
  precise float x = weight * value;
  precise float y = x * scale + 0.5f;
#ifdef __cplusplus
  int t = int(y);
  return float(t) > y ? t - 1 : t;
#else
  return int(floor(y));
#endif
}

// Whether a sample at p (leaf voxel units) can touch a leaf of a domain n leaves wide: a test on
// floats, before any conversion to int.
VOXGI_FN bool splatInDomain(vec3 p, float n) {
  return p.x > -1.0f && p.y > -1.0f && p.z > -1.0f && p.x < n + 1.0f && p.y < n + 1.0f &&
         p.z < n + 1.0f;
}

VOXGI_NAMESPACE_END
#endif
