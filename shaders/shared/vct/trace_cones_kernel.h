// The trace_cones stage's per-pixel work, shared by cpu/vct/trace_cones.cpp and
// shaders/vct/trace_cones.comp: shadow cones toward the lights (FETCH(lightAt)), the diffuse cone
// set, the specular cone and ambient occlusion, with the cone tracer of cone_kernel.h.
#ifndef VOXGI_TRACE_CONES_KERNEL_H
#define VOXGI_TRACE_CONES_KERNEL_H
#include "cone_kernel.h"
#include "../area_light.h"

VOXGI_NAMESPACE_BEGIN

// Everything trace_cones computes for the surface point p (voxel-local) with unit normal n facing
// the camera: direct light with a shadow cone per shadow-casting light, the diffuse cone set, the
// specular cone along the mirror direction, and ambient occlusion.
VOLUME_FN PixelLight tracePixel(VOLUMES_IN vec3 p, vec3 n, ObjectData object,
                                ConeTraceParams params) {
  PixelLight r;
  r.directDiffuse = vec3(0.0f);
  r.directSpecular = vec3(0.0f);
  r.indirectDiffuse = vec3(0.0f);
  r.indirectSpecular = vec3(0.0f);
  r.ambientOcclusion = 0.0f;
  float maxDistance = params.march.w;
  precise vec3 origin = p + n * params.march.y;
  precise vec3 view = normalize3(vec3(params.camera) - p);
  precise vec3 mirror = n * (2.0f * dot3(n, view)) - view;
  bool specular = object.specular.x > 0.0f;
  float shininess = object.specular.y;
  int shadowKind = params.modes.z == 1 ? kMarchShadowKahl : kMarchShadow;
  float minVisibility = 1.0f;
  precise float lightAngle = 0.0f;
  for (int i = 0; i < params.modes.x; ++i) {
    LightData l = FETCH(lightAt)(i);
    vec3 toLight;
    float distance;
    // What arrives is radiance x weight x visibility: a point, spot or directional light's
    // irradiance E x cos, or a triangle's radiance L x pi F (its form factor, the cosine
    // included), whose shadow cone is as wide as the triangle (at most shadow.aperture) and stops
    // short of its voxels.
    vec3 radiance;
    float weight;
    float cosine;
    float tanHalf = params.shadow.x;
    float shadowLength;
    if (l.info.x == kLightTriangle) {
      float f = triangleFormFactor(l, p, n, toLight, distance);
      if (f <= 0.0f) continue;
      cosine = max(dot3(n, toLight), 0.0f);
      radiance = vec3(l.intensity);
      weight = kPi * f;
      tanHalf = min(l.direction.w / distance, params.shadow.x);
      shadowLength = triangleShadowLength(distance, l.direction.w);
    } else {
      radiance = lightIrradiance(l, p, params.shadow.w, toLight, distance);
      if (radiance == vec3(0.0f)) continue;
      cosine = dot3(n, toLight);
      if (cosine <= 0.0f) continue;
      weight = cosine;
      shadowLength = distance;
    }
    float visibility = 1.0f;
    if (l.info.y == 1u && shadowLength > 0.0f)
      visibility = 1.0f - marchCone(VOLUMES origin, toLight, cosine, tanHalf,
                                    min(shadowLength, maxDistance), shadowKind, params)
                              .occlusion;
    minVisibility = min(minVisibility, visibility);
    precise vec3 arriving = radiance * (weight * visibility);
    r.directDiffuse = r.directDiffuse + arriving * kInvPi;
    if (specular) {
      precise float rl = dot3(mirror, toLight);
      r.directSpecular = r.directSpecular + arriving * phongLobe(rl, shininess);
      if (params.modes.w == 1) {
        // [Kahl 2019, eq. 5.6]: (1 - max(0, angle - grace) / pi)^q with grace = 0.008 pi shininess.
        precise float late = max(acosApprox(rl) - params.specular.y * shininess, 0.0f);
        lightAngle = lightAngle + powApprox(1.0f - late * kInvPi, params.specular.x);
      }
    }
  }
  int diffuseKind = params.modes.y == 1 ? kMarchFirstHit : kMarchRadiance;
  r.indirectDiffuse = gatherDiffuse(VOLUMES origin, n, diffuseKind, params, r.ambientOcclusion);
  // [Kahl 2019, eq. 5.9] darkens first-hit diffuse light by the smallest shadow-cone visibility.
  if (params.modes.y == 1) r.indirectDiffuse = r.indirectDiffuse * minVisibility;
  if (specular) {
    ConeHit h = marchCone(VOLUMES origin, mirror, dot3(n, mirror), object.specular.x, maxDistance,
                          kMarchRadiance, params);
    r.indirectSpecular = params.modes.w == 1 ? h.radiance * lightAngle : h.radiance;
  }
  return r;
}

VOXGI_NAMESPACE_END
#endif
