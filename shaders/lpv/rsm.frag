#version 450 core
// rsm: the visible surface's flux, facing normal, depth and triangle per texel of view uView,
// with the CPU's texel ray (shaders/shared/lpv/rsm_kernel.h) deciding which side faces the light
// and where on it the albedo texture is read (shaders/shared/surface_hit.h).
#include "shared/texture_layout.h"
#include "texture_access.glsl"
#include "shared/surface_hit.h"
#include "shared/lpv/rsm_kernel.h"

#include "surface_vertices.glsl"
layout(std430, binding = 1) readonly buffer Triangles { SurfaceTriangle triangles[]; };
layout(std430, binding = 2) readonly buffer Materials { MaterialData materials[]; };
layout(std430, binding = 3) readonly buffer Views {
  RsmParams params;
  RsmView views[];
};
layout(std430, binding = 4) readonly buffer Lights { LightData lights[]; };
uniform int uView;

in vec3 vPosition;
layout(location = 0) out vec4 outFlux;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outDepth;
layout(location = 3) out uint outPrimitiveId;

void main() {
  SurfaceTriangle t = triangles[gl_PrimitiveID];
  RsmView v = views[uView];
  int resolution = params.resolution;
  float voxelSize = params.voxelSize;
  vec3 origin, dir;
  rsmTexelRay(v, ivec2(gl_FragCoord.xy), resolution, origin, dir);
  precise float depth = dot3(vPosition - vec3(v.origin), vec3(v.forward));
  int first = 3 * gl_PrimitiveID;
  vec3 b = rayTriangleHit(origin, dir, surfaceVertex(first), surfaceVertex(first + 1),
                          surfaceVertex(first + 2));
  float footprint = rsmFootprint(v, dir, b.z, resolution, voxelSize);
  vec3 albedo = surfaceAlbedo(t, materials[t.material], b.xy,
                              surfaceFootprint(t, rsmTexelSide(v, b.z, resolution)));
  vec3 p = rsmHitPoint(origin, dir, b.z);
  outFlux = vec4(rsmFlux(lights[v.light], p, albedo, footprint, voxelSize), 0.0f);
  outNormal = vec4(facingNormal(t.normal.xyz, dir), 0.0f);
  outDepth = vec4(depth, 0.0f, 0.0f, 0.0f);
  outPrimitiveId = uint(gl_PrimitiveID) + 1u;
}
