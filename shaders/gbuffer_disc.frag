#version 450 core
// gbuffer for point clouds: the pixel's camera ray (shaders/shared/camera.h) meets the disc's
// plane where the CPU's Embree disc would, and fragments outside the radius are dropped, so both
// backends see the same circle; ties at its edge are the diff's (validation/edge_ties.cpp).
#include "shared/camera.h"
#include "shared/gbuffer_kernel.h"

layout(std430, binding = 2) readonly buffer Materials { MaterialData materials[]; };
layout(std430, binding = 3) readonly buffer Discs { SurfaceDisc discs[]; };
uniform vec3 uOrigin;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalfFov;
uniform float uAspect;
uniform vec2 uSize;
uniform uint uTriangleCount;

flat in int vDisc;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outAlbedo;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmission;
layout(location = 5) out uint outObjectId;
layout(location = 6) out uint outPrimitiveId;

void main() {
  SurfaceDisc d = discs[vDisc];
  vec3 dir = pixelDirection(uForward, uRight, uUp, uTanHalfFov, uAspect, gl_FragCoord.xy, uSize);
  vec3 n = d.normal.xyz;
  float facing = dot(dir, n);
  if (facing == 0.0f) discard;
  precise float t = dot(d.center.xyz - uOrigin, n) / facing;
  precise vec3 p = uOrigin + dir * t;
  vec3 off = p - d.center.xyz;
  if (t <= 0.0f || dot(off, off) > d.radius * d.radius) discard;
  MaterialData m = materials[d.material];
  outPosition = vec4(p, 0.0f);
  outNormal = vec4(facingNormal(n, dir), 0.0f);
  outAlbedo = vec4(d.albedo, 0.0f);
  outSpecular = m.specular;
  outEmission = m.emission;
  outObjectId = d.objectId;
  outPrimitiveId = uTriangleCount + uint(vDisc) + 1u;
}
