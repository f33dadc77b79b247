// Where a pixel's (or a shadow map texel's) ray meets the triangle it sees, and the material's
// textured values there, shared by cpu/gbuffer.cpp, cpu/lpv/rsm.cpp (the triangle Embree found) and
// shaders/gbuffer.frag, lpv/rsm.frag (the triangle rasterized, gl_PrimitiveID): both solve the same
// ray against the same float vertices, so they read the same texture coordinates and footprint bit
// for bit, where the rasterizer's interpolated attributes would differ from the ray's by a few ULP
// (docs/textures.md).
#ifndef VOXGI_SURFACE_HIT_H
#define VOXGI_SURFACE_HIT_H
#include "gbuffer_kernel.h"
#include "texture_kernel.h"
#include "vector_math.h"

VOXGI_NAMESPACE_BEGIN

// Where the ray origin + s d meets the plane of triangle (v0, v1, v2): (b1, b2, s), b1 and b2 the
// barycentric weights of v1 and v2 (Cramer's rule as in Möller and Trumbore's test, without its
// inside test: the caller knows the ray sees this triangle), clamped to the triangle so that a
// pixel on an edge reads the texture inside it. A ray parallel to the plane gives (0, 0, 0).
VOXGI_FN vec3 rayTriangleHit(vec3 origin, vec3 d, vec3 v0, vec3 v1, vec3 v2) {
  precise vec3 e1 = v1 - v0;
  precise vec3 e2 = v2 - v0;
  precise vec3 p = cross3(d, e2);
  precise float det = dot3(e1, p);
  if (det == 0.0f) return vec3(0.0f);
  precise vec3 s = origin - v0;
  precise vec3 q = cross3(s, e1);
  precise float b1 = clamp(dot3(s, p) / det, 0.0f, 1.0f);
  precise float b2 = clamp(dot3(d, q) / det, 0.0f, 1.0f - b1);
  precise float t = dot3(e2, q) / det;
  return vec3(b1, b2, t);
}

// Texture coordinates at barycentric weights b of v1 and v2.
VOXGI_FN vec2 surfaceTexcoord(SurfaceTriangle t, vec2 b) {
  precise vec2 uv = (t.uv0 + b.x * (t.uv1 - t.uv0)) + b.y * (t.uv2 - t.uv0);
  return uv;
}

// The filter footprint (uv units) of a ray's pixel or texel whose side is `side` voxels where it
// meets the triangle, measured facing the ray (for a perspective camera the distance along the
// view axis times the side at depth 1, 2 tan(fov/2) / height): that side times the triangle's uv
// per voxel. A surface seen at a slant covers more texture along one axis; the isotropic filter
// keeps the sharper one.
VOXGI_FN float surfaceFootprint(SurfaceTriangle t, float side) {
  precise float f = side * t.uvPerVoxel;
  return f;
}

// The albedo and emission of a triangle's material at barycentric weights b.
VOLUME_FN vec3 surfaceAlbedo(VOLUMES_IN SurfaceTriangle t, MaterialData m, vec2 b,
                             float footprint) {
  return texturedValue(VOLUMES vec3(m.albedo), m.textures.x, surfaceTexcoord(t, b), footprint);
}
VOLUME_FN vec3 surfaceEmission(VOLUMES_IN SurfaceTriangle t, MaterialData m, vec2 b,
                               float footprint) {
  return texturedValue(VOLUMES vec3(m.emission), m.textures.y, surfaceTexcoord(t, b), footprint);
}

VOXGI_NAMESPACE_END
#endif
