#version 450 core
// gbuffer: the visible surface's position, facing normal, material and ids per pixel, with the
// CPU's camera ray (shaders/shared/camera.h) deciding which side of the triangle faces the viewer
// and where on it the textures are read (shaders/shared/surface_hit.h).
#include "shared/camera.h"
#include "shared/texture_layout.h"
#include "texture_access.glsl"
#include "shared/surface_hit.h"

#include "surface_vertices.glsl"
layout(std430, binding = 1) readonly buffer Triangles { SurfaceTriangle triangles[]; };
layout(std430, binding = 2) readonly buffer Materials { MaterialData materials[]; };
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalfFov;
uniform float uAspect;
uniform vec2 uSize;
uniform vec3 uOrigin;
uniform float uPixelSide;

in vec3 vPosition;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outAlbedo;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmission;
layout(location = 5) out uint outObjectId;
layout(location = 6) out uint outPrimitiveId;

void main() {
  SurfaceTriangle t = triangles[gl_PrimitiveID];
  MaterialData m = materials[t.material];
  vec3 d = pixelDirection(uForward, uRight, uUp, uTanHalfFov, uAspect, gl_FragCoord.xy, uSize);
  outPosition = vec4(vPosition, 0.0f);
  outNormal = vec4(facingNormal(t.normal.xyz, d), 0.0f);
  int first = 3 * gl_PrimitiveID;
  vec3 b = rayTriangleHit(uOrigin, d, surfaceVertex(first), surfaceVertex(first + 1),
                          surfaceVertex(first + 2));
  float footprint = surfaceFootprint(t, b.z * uPixelSide);
  outAlbedo = vec4(surfaceAlbedo(t, m, b.xy, footprint), m.albedo.a);
  outSpecular = m.specular;
  outEmission = vec4(surfaceEmission(t, m, b.xy, footprint), m.emission.a);
  outObjectId = t.objectId;
  outPrimitiveId = uint(gl_PrimitiveID) + 1u;
}
