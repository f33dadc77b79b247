// The reflective shadow map's arithmetic [Dachsbacher & Stamminger 2005; Martin 2012, §3.1],
// shared by the rsm stage (CPU rays, GPU rasterizer), inject (a VPL per texel) and shade
// (the depth as a shadow map) and inject_geometry (its surfaces as blockers): the ray of a
// texel, the flux its surface reflects, where a point falls in a view, the texel's blocker.
//
// A texel's flux is rho E_perp A_perp: the irradiance on a plane facing the light times the
// texel's cross-section perpendicular to its ray, so the surface's cosine is in the footprint and
// not applied again (Martin's Φ = A_s I_s Ω_s (n_s·l)+ counts it twice, A4 of docs/lpv.md).
//
#ifndef VOXGI_LPV_RSM_KERNEL_H
#define VOXGI_LPV_RSM_KERNEL_H
#include "../area_light.h"
#include "lpv_types.h"

VOXGI_NAMESPACE_BEGIN

// Texel (x, y)'s centre on the view's [-1, 1]^2 image plane, row 0 at the top.
VOXGI_FN vec2 rsmTexelPlane(ivec2 texel, int resolution) {
  precise float px = 2.0f * (float(texel.x) + 0.5f) / float(resolution) - 1.0f;
  precise float py = 1.0f - 2.0f * (float(texel.y) + 0.5f) / float(resolution);
  return vec2(px, py);
}

// The texel's ray origin + t dir: dir's component along forward is 1, so t is the depth along
// the view's axis (the rsm_depth buffer), in cells.
VOXGI_FN void rsmTexelRay(RsmView v, ivec2 texel, int resolution, OUT(vec3) origin, OUT(vec3) dir) {
  vec2 plane = rsmTexelPlane(texel, resolution);
  precise float px = plane.x * v.extent, py = plane.y * v.extent;
  if (v.perspective == 1) {
    origin = vec3(v.origin);
    dir = (vec3(v.forward) + vec3(v.right) * px) + vec3(v.up) * py;
  } else {
    origin = (vec3(v.origin) + vec3(v.right) * px) + vec3(v.up) * py;
    dir = vec3(v.forward);
  }
}

// The texel's cross-section perpendicular to its ray at depth t, in world units^2: a perspective
// texel of side a = 2 tan / R on the plane at depth 1 subtends a^2 / |dir|^3 steradians (the
// midpoint rule), times the squared distance (t |dir|)^2.
VOXGI_FN float rsmFootprint(RsmView v, vec3 dir, float depth, int resolution, float voxelSize) {
  if (v.perspective == 1) {
    precise float side = (2.0f * v.extent / float(resolution)) * depth * voxelSize;
    precise float area = side * side / length3(dir);
    return area;
  }
  precise float side = (2.0f * v.extent / float(resolution)) * voxelSize;
  return side * side;
}

// Where a texel's ray meets its surface, s along it (rayTriangleHit's z): the point both backends
// compute the texel's flux at. Neither Embree's distance nor the rasterizer's interpolation:
// those round differently, and an emitter's irradiance turns on within an ULP of its plane.
VOXGI_FN vec3 rsmHitPoint(vec3 origin, vec3 dir, float s) {
  precise vec3 p = origin + dir * s;
  return p;
}

// The side of the texel's cross-section at distance s along its ray (the depth, its direction
// having unit component along the view axis), in cells: the scale of its texture footprint
// (shared/surface_hit.h).
VOXGI_FN float rsmTexelSide(RsmView v, float s, int resolution) {
  precise float side = 2.0f * v.extent / float(resolution);
  if (v.perspective == 1) side = side * s;
  return side;
}

// How far in front of an emissive triangle's plane (cells) a point must lie to receive its light
// in the RSM. Lambert's formula gives 0 in the plane and grows with the distance from it; a hit
// in the plane itself (the emitter's other triangle, a surface flush with it) sums edge terms
// that cancel only in exact arithmetic, and a ray hit and a rasterized fragment round them
// differently.
const float kTrianglePlaneMargin = 1e-3f;

// The irradiance an emissive triangle (kLightTriangle) of radiance L delivers at p to a plane
// facing its centroid: pi L F by Lambert's formula (shaders/shared/area_light.h), the E_perp of
// its reflective shadow map, whose views start at the centroid.
VOXGI_FN vec3 triangleFacingIrradiance(LightData l, vec3 p) {
  precise vec3 normal =
      cross3(vec3(l.direction) - vec3(l.position), vec3(l.falloff) - vec3(l.position));
  precise float height = dot3(normal, p - vec3(l.position));
  if (!(height > kTrianglePlaneMargin * length3(normal))) return vec3(0.0f);
  precise vec3 centre = ((vec3(l.position) + vec3(l.direction)) + vec3(l.falloff)) / 3.0f;
  precise vec3 toCentre = centre - p;
  float d = length3(toCentre);
  if (d == 0.0f) return vec3(0.0f);
  vec3 toLight;
  float distance;
  float f = triangleFormFactor(l, p, toCentre / d, toLight, distance);
  precise vec3 e = vec3(l.intensity) * (kPi * f);
  return e;
}

// The flux the texel's surface at p (albedo rho) reflects: rho E_perp(p) A_perp. Zero outside a
// spot's cone and behind an emissive triangle.
VOXGI_FN vec3 rsmFlux(LightData l, vec3 p, vec3 albedo, float footprint, float voxelSize) {
  vec3 toLight;
  float distance;
  vec3 e = l.kind == kLightTriangle ? triangleFacingIrradiance(l, p)
                                    : lightIrradiance(l, p, voxelSize, toLight, distance);
  precise vec3 flux = albedo * (e * footprint);
  return flux;
}

// The VPL of a texel that saw a surface (depth > 0): at the hit, about the normal facing the
// light, with the texel's flux, moved half a cell along the normal when `shift`.
VOXGI_FN Vpl rsmVpl(RsmView v, ivec2 texel, int resolution, float depth, vec3 normal, vec3 flux,
                    bool shift) {
  vec3 origin, dir;
  rsmTexelRay(v, texel, resolution, origin, dir);
  precise vec3 p = origin + dir * depth;
  if (shift) p = p + normal * 0.5f;
  Vpl vpl;
  vpl.position = vec4(p, 0.0f);
  vpl.normal = vec4(normal, 0.0f);
  vpl.flux = vec4(flux, 0.0f);
  return vpl;
}

// Where p falls in view v: xy on the [-1, 1]^2 image plane, z its depth along the axis (<= 0:
// behind a perspective view).
VOXGI_FN vec3 rsmProject(RsmView v, vec3 p) {
  precise vec3 d = p - vec3(v.origin);
  precise float z = dot3(d, vec3(v.forward));
  precise float scale = v.perspective == 1 ? z * v.extent : v.extent;
  if (!(scale > 0.0f)) return vec3(0.0f, 0.0f, -1.0f);
  precise vec2 xy = vec2(dot3(d, vec3(v.right)), dot3(d, vec3(v.up))) / scale;
  return vec3(xy, z);
}

// Fixed-point units of the RSM blocker sums per cell^2. A 256^2 map's texel covers ~1e-3 cells^2,
// so 2^22 leaves rounding of ~1e-4 per texel; a cell's sum is at most its silhouette seen from
// one light (< 2 cells^2) over the clamped cosine (x 10), widened by the perspective within the
// cell (< x 4 beside the light): < 80 cells^2 = 3.4e8 units, a sixth of int32's range.
const float kBlockerScale = 4194304.0f;

// The surface an RSM texel saw (depth > 0) as fixed-point (area, area x normal) in kBlockerScale
// units, and the GV cell it lands in: the one centred on the LPV cell corner nearest the hit. The
// true area is the texel's cross-section over the cosine to its ray, with the cosine clamped at
// 0.1 (a grazing texel's area grows without bound: past 84 degrees it counts as at 84).
VOXGI_FN ivec4 rsmBlocker(RsmView v, ivec2 texel, int resolution, float depth, vec3 normal,
                          OUT(ivec3) cell) {
  vec3 origin, dir;
  rsmTexelRay(v, texel, resolution, origin, dir);
  precise vec3 p = origin + dir * depth;
  cell = ivec3(floor(p + vec3(0.5f))) - ivec3(1);
  precise float cosine = abs(dot3(normal, dir)) / length3(dir);
  precise float units =
      rsmFootprint(v, dir, depth, resolution, 1.0f) / max(cosine, 0.1f) * kBlockerScale;
  precise vec3 weighted = normal * units;
  return ivec4(int(floor(units + 0.5f)), int(floor(weighted.x + 0.5f)),
               int(floor(weighted.y + 0.5f)), int(floor(weighted.z + 0.5f)));
}

VOXGI_NAMESPACE_END
#endif
