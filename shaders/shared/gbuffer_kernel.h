// What a pixel stores about the surface it sees, shared by cpu/gbuffer.cpp (Embree hit) and
// shaders/gbuffer.frag, gbuffer_disc.frag (rasterized fragment): the normal turned toward the
// camera and the material's attributes.
#ifndef VOXGI_GBUFFER_KERNEL_H
#define VOXGI_GBUFFER_KERNEL_H
#include "vector_math.h"

VOXGI_NAMESPACE_BEGIN

// One triangle's surface (std430), indexed by gl_PrimitiveID on the GPU and by Embree's primitive
// id on the CPU.
struct SurfaceTriangle {
  vec4 normal;    // xyz: unit normal (right-handed winding), 0 if degenerate
  uint objectId;  // mesh index + 1
  uint material;  // index into the materials
  uint pad0;
  uint pad1;
  vec2 uv0;  // texture coordinates of the three vertices (shared/surface_hit.h)
  vec2 uv1;
  vec2 uv2;
  float uvPerVoxel;  // uv units per voxel of length on the triangle: sqrt(uv area / area)
  uint pad2;
};

// One point of a cloud as the disc the gbuffer sees (std430), after the scene's triangles in the
// primitive numbering: Embree's oriented disc on the CPU, a quad in its plane cut to the circle on
// the GPU (shaders/gbuffer_disc.vert).
struct SurfaceDisc {
  vec3 center;   // voxel-local
  float radius;  // voxels
  vec3 normal;   // unit
  float pad0;
  vec3 albedo;  // the point's colour, or its material's albedo
  float pad1;
  uint objectId;  // mesh count + cloud index + 1
  uint material;  // index into the materials
  uint pad2;
  uint pad3;
};

// One material (std430).
struct MaterialData {
  vec4 albedo;     // rgb
  vec4 specular;   // rgb: specular colour; a: Phong shininess
  vec4 emission;   // rgb
  uvec4 textures;  // x: albedo texture, y: emission texture (kNoTexture: none)
};

// The surface normal facing the viewer: `normal` flipped when the camera sees its back.
VOXGI_FN vec3 facingNormal(vec3 normal, vec3 viewDir) {
  return dot3(normal, viewDir) > 0.0f ? -normal : normal;
}

VOXGI_NAMESPACE_END
#endif
