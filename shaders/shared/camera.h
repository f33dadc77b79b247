// The camera ray through a pixel centre, shared by the CPU gbuffer (ray casting) and the GPU
// gbuffer (to turn the normal toward the viewer exactly as the CPU does). Row 0 is the top row.
#ifndef VOXGI_CAMERA_H
#define VOXGI_CAMERA_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// `centre`: pixel centre (x + 0.5, y + 0.5); `size`: image width, height. Not normalised.
VOXGI_FN vec3 pixelDirection(vec3 forward, vec3 right, vec3 up, float tanHalfFov, float aspect,
                             vec2 centre, vec2 size) {
  precise float px = (2.0f * centre.x / size.x - 1.0f) * tanHalfFov * aspect;
  precise float py = (1.0f - 2.0f * centre.y / size.y) * tanHalfFov;
  precise vec3 d = (forward + right * px) + up * py;
  return d;
}

VOXGI_NAMESPACE_END
#endif
