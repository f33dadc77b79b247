// The records the cone tracer exchanges with the host (std430 where uploaded),
// separate from shaders/shared/cone/march.h so a shader can declare its FETCH functions
// (pyramidAt, lightAt, coneAt) between the two.
#ifndef VOXGI_CONE_TYPES_H
#define VOXGI_CONE_TYPES_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// The cone marcher's parameters (std430, 128 bytes), shared by vct's trace_cones and bounce and
// the octree's gather and shade; common/cone/cone_trace.cpp fills them from the settings. Lengths
// are in voxels unless named otherwise.
struct ConeTraceParams {
  int resolution;          // N voxels per axis
  int topLevel;            // the coarsest pyramid level a cone samples: log2 N (octree: depth - 1)
  int directional;         // 1: the levels above 0 hold six directional faces (mip=anisotropic)
  int diffuseConeCount;    // cones of the diffuse set (FETCH(coneAt)); 0: none traced
  int lightCount;          // analytic lights (FETCH(lightAt))
  int firstHitDiffuse;     // 1: cones.diffuse=first_hit
  int kahlShadow;          // 1: shadow.falloff=kahl2019
  int lightAngleSpecular;  // 1: specular.brdf=light_angle
  int ambientOcclusion;    // 1: diffuse cones accumulate ambient occlusion
  int maxSteps;            // steps per cone at most, enough to leave the grid
  int diffuseScale;        // trace_cones: diffuse cones once per scale x scale pixels (upsampled)
  int pad1;
  float coneStep;               // beta: a step is beta times the cone's diameter (cones.step)
  float coneOffset;             // a cone starts this far above its surface
  float minStep;                // no step is shorter
  float maxDistance;            // no cone goes further
  float tanHalfShadowAperture;  // the shadow cone's tan(half aperture) (shadow.aperture)
  float shadowStrength;         // Kahl's strength (shadow.strength)
  float ambientLambda;          // the occlusion falloff lambda (ao.lambda)
  float voxelSize;              // world units per voxel, for the lights' falloff
  float specularFalloff;        // Kahl's light-angle exponent q (specular.falloff)
  float specularGrace;          // Kahl's angular grace per unit of shininess (radians)
  float coneClearance;  // the largest sampled voxel per voxel of height above the cone's own
                        // surface (cones.clearance; 0: no bound)
  float pad2;
  vec4 background;  // rgb: radiance where a cone leaves the grid
  vec4 camera;      // xyz: the camera's position, voxel-local
};

// One diffuse cone (std430): direction in the tangent frame (z along the normal).
struct ConeData {
  vec3 direction;  // unit
  float tanHalfAperture;
  float weight;  // of the cone's mean radiance in E / pi
  float pad0;
  float pad1;
  float pad2;
};

// Per object id (mesh index + 1; 0 is the background), std430.
struct ObjectData {
  float specularTanHalfAperture;  // the specular cone's; 0: none traced
  float shininess;                // Phong
  float pad0;
  float pad1;
};

// What trace_cones leaves for compose: irradiance terms still to be multiplied by the material.
struct PixelLight {
  vec3 directDiffuse;      // sum over lights of E cos V / pi
  vec3 directSpecular;     // sum over lights of E cos V (n+2)/(2 pi) max(r.l, 0)^n
  vec3 indirectDiffuse;    // cone-traced E / pi
  vec3 indirectSpecular;   // cone-traced radiance around the mirror direction
  float ambientOcclusion;  // delta of [Villegas 2017, §4.2], weighted over the diffuse cones
};

// At cones.diffuse_scale = s > 1, the diffuse light traced once for an s x s block of pixels
// (shaders/shared/vct/diffuse_upsample.h), std430, 64 bytes.
struct DiffuseSample {
  vec4 position;  // xyz: the sample pixel's surface point (voxel-local); w: 1, or 0 for a block
                  // without a surface (it stands for no pixel)
  vec4 normal;    // xyz: unit
  vec4 radiance;  // xyz: the sample's DiffuseSum.radiance
  vec4 sums;      // x: its DiffuseSum.ambient, y: its DiffuseSum.weights
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
