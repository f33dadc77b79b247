// Analytic lights shared by light_voxels (per voxel) and compose (per pixel): the std430 light
// record and the irradiance a light delivers at a point, with [Kahl 2019, §2.1.5]'s falloff models.
// Same semantics as the path tracer (validation/reference/path_trace.cpp): hard spot cut-off at
// half the spot angle, falloff on world-space distance.
#ifndef VOXGI_LIGHTING_H
#define VOXGI_LIGHTING_H
#include "approx_math.h"
#include "vector_math.h"

VOXGI_NAMESPACE_BEGIN

const uint kLightPoint = 0u;
const uint kLightSpot = 1u;
const uint kLightDirectional = 2u;
const uint kLightTriangle =
    3u;  // an emissive triangle as an area light (emitters.mode=area_lights)

// One light in voxel-local coordinates (common/lights.cpp builds them). 80 bytes, std430. A
// triangle (kLightTriangle) keeps its three corners in position, direction and falloff (xyz,
// counter-clockwise seen from the side it emits to), its radiance in intensity and its bounding
// radius (shaders/shared/area_light.h).
struct LightData {
  vec3 position;         // voxel-local (point, spot)
  float boundingRadius;  // a triangle's, about its centroid (voxels)
  vec3 direction;        // unit direction the light travels (spot axis, directional)
  float spotCosine;      // cos(half spot angle)
  vec3 intensity;        // W/sr (point, spot) or irradiance (directional)
  float pad0;
  vec3 falloff;           // constant, linear, quadratic coefficients (world units)
  int polynomialFalloff;  // 1: the polynomial falloff, 0: inverse square
  uint kind;              // kLight*
  uint castsShadows;      // 1: a shadow ray or cone tests it
  uint pad1;
  uint pad2;
};

// Irradiance on a plane facing the light at p (voxel-local), without the cosine. `toLight` gets
// the unit direction toward the light and `distance` the distance in voxels (1e30 for a
// directional light). `voxelSize` converts voxels to world units for the falloff.
VOXGI_FN vec3 lightIrradiance(LightData l, vec3 p, float voxelSize, OUT(vec3) toLight,
                              OUT(float) distance) {
  if (l.kind == kLightDirectional) {
    toLight = -vec3(l.direction);
    distance = 1e30f;
    return vec3(l.intensity);
  }
  precise vec3 d = vec3(l.position) - p;
  distance = length3(d);
  if (distance == 0.0f) {
    toLight = vec3(0.0f);
    return vec3(0.0f);
  }
  toLight = d / distance;
  if (l.kind == kLightSpot && dot3(-toLight, vec3(l.direction)) < l.spotCosine) return vec3(0.0f);
  precise float r = distance * voxelSize;
  precise float att = l.polynomialFalloff == 0
                          ? 1.0f / (r * r)
                          : 1.0f / ((l.falloff.x + l.falloff.y * r) + l.falloff.z * (r * r));
  precise vec3 e = vec3(l.intensity) * att;
  return e;
}

// The normalised Phong lobe (n + 2) / (2 pi) max(r.l, 0)^n of a light direction at cosine `rl` to
// the mirror direction: what a light's irradiance contributes to the specular term.
VOXGI_FN float phongLobe(float rl, float shininess) {
  precise float lobe = (shininess + 2.0f) * (0.5f * kInvPi) * powApprox(rl, shininess);
  return lobe;
}

// Villegas' normal-weighted attenuation ([Villegas 2017, §2.1]): per-face cosines D = (l.x, l.y,
// l.z), each taken on the side the normal points to, weighted by W = n^2. Equals max(n.l, 0) when n
// is an axis; is positive wherever a face of the voxel the normal leans toward sees the light.
VOXGI_FN float normalWeightedAttenuation(vec3 n, vec3 l) {
  precise vec3 w = n * n;
  precise vec3 d = vec3(n.x > 0.0f ? max(l.x, 0.0f) : max(-l.x, 0.0f),
                        n.y > 0.0f ? max(l.y, 0.0f) : max(-l.y, 0.0f),
                        n.z > 0.0f ? max(l.z, 0.0f) : max(-l.z, 0.0f));
  return dot3(w, d);
}

VOXGI_NAMESPACE_END
#endif
