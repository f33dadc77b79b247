#version 450 core
// shade: per pixel, the shared cone tracer's direct light (shadow cones) and specular cone
// through the octree's bricks (shaders/shared/cone/pixel_light.h, no diffuse cones), the
// leaves' gathered light through their bricks (shaders/shared/svo/shade_kernel.h), composed as
// the dense technique composes (shaders/shared/compose.h). The twin of
// cpu/svo/shade.cpp.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/lighting.h"
#include "shared/cone/cone_types.h"
#include "svo_tree.glsl"
#define SVO_SOURCE_BINDING 1
#define SVO_FACES_BINDING 2
#include "svo_pyramid.glsl"

// The light as halves (shared/half_float.h, packHalves), as the tree's buffers hold it.
layout(std430, binding = 3) readonly buffer Bricks { uvec2 bricks[]; };  // 27 a leaf tile
// The cones' levels as bricks (gpu/svo/bricks.cpp, completeBricks), as propagate_gather.comp
// reads them: one walk and eight texels a trilinear cell.
layout(std430, binding = 8) readonly buffer LeafBricks { uvec2 leafBricks[]; };  // 27 a leaf tile
layout(std430, binding = 9) readonly buffer NodeBricks { uvec2 nodeBricks[]; };  // 27 x 6 a tile
vec4 svoBrickAt(int level, int face, uint tile, uint texel);
#include "shared/svo/svo_sample.h"
vec4 svoBrickAt(int level, int face, uint tile, uint texel) {
  uint e = tile * uint(kBrickTexels) + texel;
  if (face == kSvoGatheredFace) return unpackHalves(bricks[e]);
  return unpackHalves(level == uDepth ? leafBricks[e] : nodeBricks[e * 6u + uint(face)]);
}
// Pyramid level `level` is tree level uDepth - level (svo_pyramid.glsl).
vec4 filterBrickCell(int level, int face, TrilinearCell c) {
  return svoFilterCell(uDepth - level, face, c);
}
#define VOXGI_BRICK_CELLS

LightData lightAt(int i);  // defined below, after the buffers
ConeData coneAt(int i) {  // no diffuse cones here
  return ConeData(vec3(0.0f), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
}

#include "shared/cone/pixel_light.h"
#include "shared/svo/shade_kernel.h"
#include "shared/compose.h"

layout(std430, binding = 4) readonly buffer Lights {
  ConeTraceParams params;
  LightData lights[];
};
layout(std430, binding = 5) readonly buffer Objects { ObjectData objects[]; };
// per pixel: position and object id (its bits), normal, albedo, specular and shininess, emission
layout(std430, binding = 6) readonly buffer Pixels { vec4 pixels[]; };
// per pixel: direct diffuse, direct specular, indirect diffuse, indirect specular, colour
layout(std430, binding = 7) writeonly buffer Terms { vec4 terms[]; };
layout(location = 1) uniform int uWidth;
layout(location = 2) uniform int uHeight;
uniform vec3 uBackground;
uniform bool uTricubic;  // shade.filter

LightData lightAt(int i) { return lights[i]; }

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= uWidth || px.y >= uHeight) return;
  uint e = uint(px.y * uWidth + px.x);
  vec4 position = pixels[5u * e];
  uint id = floatBitsToUint(position.w);
  PixelLight l = PixelLight(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
  vec3 color = uBackground;
  if (id != 0u) {
    l = tracePixel(position.xyz, pixels[5u * e + 1u].xyz, objects[id], params);
    l.indirectDiffuse = uTricubic ? svoIrradianceTricubic(position.xyz, uDepth)
                                  : svoIrradiance(position.xyz, uDepth);
    color = composePixel(id, pixels[5u * e + 2u].xyz, pixels[5u * e + 3u].xyz,
                         pixels[5u * e + 4u].xyz, l.directDiffuse, l.directSpecular,
                         l.indirectDiffuse, l.indirectSpecular, 0.0f, uBackground);
  }
  terms[5u * e] = vec4(l.directDiffuse, 0.0f);
  terms[5u * e + 1u] = vec4(l.directSpecular, 0.0f);
  terms[5u * e + 2u] = vec4(l.indirectDiffuse, 0.0f);
  terms[5u * e + 3u] = vec4(l.indirectSpecular, 0.0f);
  terms[5u * e + 4u] = vec4(color, 0.0f);
}
