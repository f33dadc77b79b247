// The records the cone tracer exchanges with the host (std430 where uploaded),
// separate from shaders/shared/vct/cone_kernel.h so a shader can declare its FETCH functions
// (pyramidAt, lightAt, coneAt) between the two.
#ifndef VOXGI_CONE_TYPES_H
#define VOXGI_CONE_TYPES_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// std430; common/vct/trace_cones.cpp fills it from the settings.
struct ConeTraceParams {
  ivec4 grid;     // x: N, y: pyramid levels (log2 N), z: 1 directional pyramid, w: diffuse cones
  ivec4 modes;    // x: lights, y: 1 first-hit diffuse, z: 1 Kahl shadow falloff, w: 1 light-angle
                  // specular
  ivec4 limits;   // x: 1 ambient occlusion, y: steps per cone at most, zw: 0
  vec4 march;     // x: step factor beta, y: start offset along the normal (voxels), z: min step, w:
                  // max distance
  vec4 shadow;    // x: tan(half shadow aperture), y: Kahl strength, z: AO lambda, w: voxel size
                  // (world)
  vec4 specular;  // x: Kahl falloff exponent q, y: Kahl angular grace per unit shininess
  vec4 background;  // rgb: radiance where a cone leaves the grid
  vec4 camera;      // xyz: camera position, voxel-local
  vec4 surface;     // x: cones.clearance, the largest sampled voxel per voxel of height above
                    // the cone's own surface (0: no bound)
};

// One diffuse cone (std430): direction in the tangent frame (z along the normal).
struct ConeData {
  vec4 direction;  // xyz: unit direction; w: tan(half aperture)
  vec4 weight;     // x: weight of the cone's mean radiance in E / pi
};

// Per object id (mesh index + 1; 0 is the background), std430.
struct ObjectData {
  vec4 specular;  // x: tan(half aperture) of the specular cone, 0 for none; y: Phong shininess
};

// What trace_cones leaves for compose: irradiance terms still to be multiplied by the material.
struct PixelLight {
  vec3 directDiffuse;      // sum over lights of E cos V / pi
  vec3 directSpecular;     // sum over lights of E cos V (n+2)/(2 pi) max(r.l, 0)^n
  vec3 indirectDiffuse;    // cone-traced E / pi
  vec3 indirectSpecular;   // cone-traced radiance around the mirror direction
  float ambientOcclusion;  // delta of [Villegas 2017, §4.2], weighted over the diffuse cones
};

// What shaders/vct/trace_cones.comp writes per pixel (std430, 80 bytes; PixelLight's vec3s would
// pad differently in C++ and GLSL), read back into the stage's buffers.
struct PixelTerms {
  vec4 directDiffuse;     // rgb
  vec4 directSpecular;    // rgb
  vec4 indirectDiffuse;   // rgb
  vec4 indirectSpecular;  // rgb
  vec4 ambientOcclusion;  // x
};

VOXGI_NAMESPACE_END
#endif
