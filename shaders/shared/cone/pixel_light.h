// A pixel's cones, the cone library's per-pixel work: vct's trace_cones and svo's shade run it on
// both backends (the CPU's tiles: cpu/cone/tile_tracer.h). Shadow cones toward the lights
// (FETCH(lightAt)), the diffuse cone set, the specular cone and ambient occlusion, with the cone
// tracer of march.h.
#ifndef VOXGI_CONE_PIXEL_LIGHT_H
#define VOXGI_CONE_PIXEL_LIGHT_H
#include "march.h"
#include "../area_light.h"

VOXGI_NAMESPACE_BEGIN

// trace_cones' work comes in phases so that the CPU can march the cones of several pixels at once
// (cpu/cone/cone_lanes.h) and still compute exactly what tracePixel computes: per pixel the cones'
// origin and mirror direction, per light a LightPath, its shadow cone's march and addLight, per
// diffuse cone its march and addDiffuseCone, the specular cone's march, then finishPixel.

// The point all of a pixel's cones start from: params.coneOffset voxels above p along n.
VOXGI_FN vec3 coneOrigin(vec3 p, vec3 n, ConeTraceParams params) {
  precise vec3 origin = p + n * params.coneOffset;
  return origin;
}

// The mirror direction of the view ray at p: the specular cone's axis.
VOXGI_FN vec3 mirrorDirection(vec3 p, vec3 n, ConeTraceParams params) {
  precise vec3 view = normalize3(vec3(params.camera) - p);
  precise vec3 mirror = n * (2.0f * dot3(n, view)) - view;
  return mirror;
}

// What one light sends toward the surface point, before its shadow cone.
struct LightPath {
  vec3 toLight;        // unit direction toward the light
  vec3 radiance;       // E of a point, spot or directional light; L of a triangle
  float weight;        // cos for E; pi F (the form factor, the cosine included) for L
  float cosine;        // n . toLight: the shadow cone's rise
  float tanHalf;       // the shadow cone's aperture
  float shadowLength;  // how far the shadow cone marches; 0: the light casts no shadow here
  bool arrives;        // false: nothing arrives (behind the surface, outside a spot, ...)
};

// What arrives is radiance x weight x visibility: a point, spot or directional light's irradiance
// E x cos, or a triangle's radiance L x pi F, whose shadow cone is as wide as the triangle (at
// most shadow.aperture) and stops short of its voxels.
VOXGI_FN LightPath lightPath(LightData l, vec3 p, vec3 n, ConeTraceParams params) {
  LightPath path;
  float distance;
  float shadowLength;
  path.tanHalf = params.tanHalfShadowAperture;
  path.arrives = true;
  if (l.kind == kLightTriangle) {
    float f = triangleFormFactor(l, p, n, path.toLight, distance);
    path.arrives = !(f <= 0.0f);
    path.cosine = max(dot3(n, path.toLight), 0.0f);
    path.radiance = vec3(l.intensity);
    path.weight = kPi * f;
    if (path.arrives) path.tanHalf = min(l.boundingRadius / distance, params.tanHalfShadowAperture);
    shadowLength = path.arrives ? triangleShadowLength(distance, l.boundingRadius) : 0.0f;
  } else {
    path.radiance = lightIrradiance(l, p, params.voxelSize, path.toLight, distance);
    path.cosine = dot3(n, path.toLight);
    path.arrives = path.radiance != vec3(0.0f) && !(path.cosine <= 0.0f);
    path.weight = path.cosine;
    shadowLength = distance;
  }
  path.shadowLength = path.arrives && l.castsShadows == 1u && shadowLength > 0.0f
                          ? min(shadowLength, params.maxDistance)
                          : 0.0f;
  return path;
}

// The kind of march of the shadow cones: opacity only, or with Kahl's falloff.
VOXGI_FN int shadowMarchKind(ConeTraceParams params) {
  return params.kahlShadow == 1 ? kMarchShadowKahl : kMarchShadow;
}

// The kind of march of the diffuse cones: composited radiance, or Kahl's first hit.
VOXGI_FN int diffuseMarchKind(ConeTraceParams params) {
  return params.firstHitDiffuse == 1 ? kMarchFirstHit : kMarchRadiance;
}

// Direct light summed over the lights so far.
struct DirectLight {
  vec3 diffuse;
  vec3 specular;
  float minVisibility;  // the smallest shadow-cone visibility
  float lightAngle;     // [Kahl 2019, eq. 5.6]'s sum over the lights
};

VOXGI_FN DirectLight noDirectLight() {
  DirectLight d;
  d.diffuse = vec3(0.0f);
  d.specular = vec3(0.0f);
  d.minVisibility = 1.0f;
  d.lightAngle = 0.0f;
  return d;
}

// d plus the light of `path` arriving with `visibility` (1 - its shadow cone's occlusion).
VOXGI_FN DirectLight addLight(DirectLight d, LightPath path, float visibility, vec3 mirror,
                              ObjectData object, ConeTraceParams params) {
  d.minVisibility = min(d.minVisibility, visibility);
  precise vec3 arriving = path.radiance * (path.weight * visibility);
  d.diffuse = d.diffuse + arriving * kInvPi;
  if (object.specularTanHalfAperture > 0.0f) {
    float shininess = object.shininess;
    precise float rl = dot3(mirror, path.toLight);
    d.specular = d.specular + arriving * phongLobe(rl, shininess);
    if (params.lightAngleSpecular == 1) {
      // [Kahl 2019, eq. 5.6]: (1 - max(0, angle - grace) / pi)^q with grace = 0.008 pi shininess.
      precise float late = max(acosApprox(rl) - params.specularGrace * shininess, 0.0f);
      d.lightAngle = d.lightAngle + powApprox(1.0f - late * kInvPi, params.specularFalloff);
    }
  }
  return d;
}

// trace_cones' terms from the direct light, the diffuse cones and the specular cone's march
// (unused when the object has none).
VOXGI_FN PixelLight finishPixel(DirectLight d, DiffuseSum diffuse, ConeHit specularHit,
                                ObjectData object, ConeTraceParams params) {
  PixelLight r;
  r.directDiffuse = d.diffuse;
  r.directSpecular = d.specular;
  r.indirectDiffuse = diffuse.radiance;
  r.ambientOcclusion = diffuseAmbientOcclusion(diffuse);
  // [Kahl 2019, eq. 5.9] darkens first-hit diffuse light by the smallest shadow-cone visibility.
  if (params.firstHitDiffuse == 1) r.indirectDiffuse = r.indirectDiffuse * d.minVisibility;
  r.indirectSpecular = vec3(0.0f);
  if (object.specularTanHalfAperture > 0.0f)
    r.indirectSpecular =
        params.lightAngleSpecular == 1 ? specularHit.radiance * d.lightAngle : specularHit.radiance;
  return r;
}

// Everything trace_cones computes for the surface point p (voxel-local) with unit normal n facing
// the camera but its diffuse cones, whose sum is `diffuse`: direct light with a shadow cone per
// shadow-casting light, the specular cone along the mirror direction, and ambient occlusion.
VOLUME_FN PixelLight shadePixel(VOLUMES_IN vec3 p, vec3 n, ObjectData object, DiffuseSum diffuse,
                                ConeTraceParams params) {
  vec3 origin = coneOrigin(p, n, params);
  vec3 mirror = mirrorDirection(p, n, params);
  DirectLight d = noDirectLight();
  for (int i = 0; i < params.lightCount; ++i) {
    LightPath path = lightPath(FETCH(lightAt)(i), p, n, params);
    if (!path.arrives) continue;
    float visibility = 1.0f;
    if (path.shadowLength > 0.0f)
      visibility = 1.0f - marchCone(VOLUMES origin, path.toLight, path.cosine, path.tanHalf,
                                    path.shadowLength, shadowMarchKind(params), params)
                              .occlusion;
    d = addLight(d, path, visibility, mirror, object, params);
  }
  ConeHit specularHit = noConeHit();
  if (object.specularTanHalfAperture > 0.0f)
    specularHit = marchCone(VOLUMES origin, mirror, dot3(n, mirror), object.specularTanHalfAperture,
                            params.maxDistance, kMarchRadiance, params);
  return finishPixel(d, diffuse, specularHit, object, params);
}

// The diffuse cone set of the surface point p with unit normal n.
VOLUME_FN DiffuseSum traceDiffuse(VOLUMES_IN vec3 p, vec3 n, ConeTraceParams params) {
  return gatherDiffuse(VOLUMES coneOrigin(p, n, params), n, diffuseMarchKind(params), params);
}

// Everything trace_cones computes for p with every cone traced: shadePixel with the pixel's own
// diffuse cones.
VOLUME_FN PixelLight tracePixel(VOLUMES_IN vec3 p, vec3 n, ObjectData object,
                                ConeTraceParams params) {
  return shadePixel(VOLUMES p, n, object, traceDiffuse(VOLUMES p, n, params), params);
}

VOXGI_NAMESPACE_END
#endif
