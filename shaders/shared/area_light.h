// Emissive triangles as area lights (emitters.mode=area_lights, docs/stages/vct/trace_cones.md,
// "Area lights"): the exact unoccluded irradiance a triangle of uniform radiance L delivers to a
// point, by Lambert's formula for a polygon ([Arvo 1995]), after clipping the triangle to the
// receiver's hemisphere. Shared by light_voxels (per voxel) and trace_cones (per pixel).
#ifndef VOXGI_AREA_LIGHT_H
#define VOXGI_AREA_LIGHT_H
#include "lighting.h"

VOXGI_NAMESPACE_BEGIN

// The angle between unit vectors a and b. acos loses small angles to the rounding of a.b near 1,
// so below a.b = 0.9 it is 2 asin(|a - b| / 2), by its series to the 7th power (|a - b| / 2 <=
// 0.224, remainder below 2e-7 relative).
VOXGI_FN float angleBetween(vec3 a, vec3 b) {
  float c = dot3(a, b);
  if (c < 0.9f) return acosApprox(c);
  precise float h = 0.5f * length3(a - b);
  precise float h2 = h * h;
  precise float s = h * (1.0f + h2 * (0.16666667f + h2 * (0.075f + h2 * 0.044642857f)));
  return 2.0f * s;
}

// One edge's term of Lambert's formula: the angle the edge subtends at the receiver times the
// cosine between the receiver's normal and the normal of the plane through the receiver and the
// edge. `a` and `b` are the edge's ends relative to the receiver.
VOXGI_FN float edgeTerm(vec3 a, vec3 b, vec3 n) {
  float la = length3(a);
  float lb = length3(b);
  if (la == 0.0f || lb == 0.0f) return 0.0f;
  precise vec3 ua = a / la;
  precise vec3 ub = b / lb;
  precise vec3 c = cross3(ua, ub);
  float lc = length3(c);
  if (lc == 0.0f) return 0.0f;
  precise float term = angleBetween(ua, ub) * (dot3(n, c) / lc);
  return term;
}

// What a triangle light gives the receiver at p with unit normal n: the form factor F (E = pi L F,
// the cosine included), 0 where the receiver is behind the emitting side or the triangle lies
// below its horizon. `toLight` and `distance` (voxels) point at the middle of the part above the
// horizon, which is where the shadow cone goes.
VOXGI_FN float triangleFormFactor(LightData l, vec3 p, vec3 n, OUT(vec3) toLight,
                                  OUT(float) distance) {
  toLight = vec3(0.0f);
  distance = 0.0f;
  precise vec3 v0 = vec3(l.position) - p;
  precise vec3 v1 = vec3(l.direction) - p;
  precise vec3 v2 = vec3(l.falloff) - p;
  // One-sided: the receiver must lie in front of the emitting side (counter-clockwise corners).
  precise vec3 facing = cross3(v1 - v0, v2 - v0);
  if (dot3(facing, v0) >= 0.0f) return 0.0f;
  // Sutherland-Hodgman against the receiver's tangent plane n.x > 0: at most 4 corners.
  vec3 corner[3];
  corner[0] = v0;
  corner[1] = v1;
  corner[2] = v2;
  vec3 kept[4];
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    vec3 a = corner[i];
    vec3 b = corner[i == 2 ? 0 : i + 1];
    float ha = dot3(n, a);
    float hb = dot3(n, b);
    if (ha > 0.0f) {
      kept[count] = a;
      count = count + 1;
    }
    if ((ha > 0.0f) != (hb > 0.0f)) {
      precise vec3 cut = a + (b - a) * (ha / (ha - hb));
      kept[count] = cut;
      count = count + 1;
    }
  }
  if (count < 3) return 0.0f;
  precise float sum = 0.0f;
  precise vec3 middle = vec3(0.0f);
  for (int i = 0; i < count; ++i) {
    vec3 a = kept[i];
    vec3 b = kept[i + 1 == count ? 0 : i + 1];
    sum = sum + edgeTerm(a, b, n);
    middle = middle + a;
  }
  // Corners counter-clockwise from the emitting side turn clockwise seen from the receiver.
  precise float f = -sum * (0.5f * kInvPi);
  if (!(f > 0.0f)) return 0.0f;
  middle = middle / float(count);
  distance = length3(middle);
  if (distance == 0.0f) return 0.0f;
  toLight = middle / distance;
  return f;
}

// How far a shadow cone toward a triangle light may march before its samples reach the light's
// own voxels. A cone of half-angle tan = r / d (r the triangle's bounding radius, d the distance
// to it) is w = 2 r t / d wide at t, and its quadrilinear sample reads voxels of up to 2w, whose
// trilinear filter reaches one such voxel from the sample: the samples touch the light where
// d - t = 2w, at t = d^2 / (d + 4 r). 1.5 voxels more stay clear of the light's conservative
// voxels. A cone narrowed to shadow.aperture stays clear too.
VOXGI_FN float triangleShadowLength(float distance, float radius) {
  precise float reach = distance * distance / (distance + 4.0f * radius) - 1.5f;
  return max(reach, 0.0f);
}

VOXGI_NAMESPACE_END
#endif
