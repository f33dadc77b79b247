// The final colour of a pixel from the gbuffer's material and its light terms, shared by every
// technique's last stage (vct's compose, lpv's and svo's shade) on both backends:
//   albedo (direct diffuse + indirect diffuse (1 - AO)) + specular (direct + indirect specular)
//   + emission, and the background radiance where the pixel sees no surface.
// AO multiplies the indirect diffuse term only when asked (ao.mode=on): the cones already see
// occluders, so it is an artistic contact shadow, not part of the estimate.
#ifndef VOXGI_COMPOSE_H
#define VOXGI_COMPOSE_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// One pixel's inputs for shaders/vct/compose.comp (std430, 128 bytes), packed on the host from
// the gbuffer's and trace_cones' buffers; a buffer the plan does not produce leaves its term 0.
struct ComposeInput {
  vec4 albedo;             // rgb: gbuffer.pixel_albedo
  vec4 specular;           // rgb: gbuffer.pixel_specular's colour
  vec4 emission;           // rgb: gbuffer.pixel_emission
  vec4 directDiffuse;      // rgb: trace_cones' terms
  vec4 directSpecular;     // rgb
  vec4 indirectDiffuse;    // rgb
  vec4 indirectSpecular;   // rgb
  float ambientOcclusion;  // trace_cones' AO where the light terms apply it, else 0
  float pad0;
  float pad1;
  float pad2;
};

VOXGI_FN vec3 composePixel(uint objectId, vec3 albedo, vec3 specular, vec3 emission,
                           vec3 directDiffuse, vec3 directSpecular, vec3 indirectDiffuse,
                           vec3 indirectSpecular, float ambientOcclusion, vec3 background) {
  if (objectId == 0u) return background;
  precise vec3 diffuse = directDiffuse + indirectDiffuse * (1.0f - ambientOcclusion);
  precise vec3 glossy = directSpecular + indirectSpecular;
  precise vec3 c = (albedo * diffuse + specular * glossy) + emission;
  return c;
}

VOXGI_NAMESPACE_END
#endif
