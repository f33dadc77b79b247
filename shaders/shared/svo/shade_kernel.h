// Indirect diffuse light at a pixel from the octree's leaves [Salm 2015, §4.6]: the light each
// leaf gathered in its last frame (E / pi, premultiplied by the leaf's clamped opacity) sampled
// through the leaf bricks, trilinearly or with a cubic B-spline (shade.filter), and divided by
// the opacity sampled the same way, so empty leaves around the surface do not darken it. Shared by
// both backends' shade.
#ifndef VOXGI_SVO_SHADE_KERNEL_H
#define VOXGI_SVO_SHADE_KERNEL_H
#include "svo_sample.h"

VOXGI_NAMESPACE_BEGIN

// E / pi at p (leaf units) of a tree of `depth`, from FETCH(svoBrickAt)(depth, kSvoGatheredFace,
// leaf tile, texel): rgb the premultiplied gathered light, a the opacity.
VOLUME_FN vec3 svoIrradiance(VOLUMES_IN vec3 p, int depth) {
  TrilinearCell c = trilinearCell(0, p, 1 << depth);
  vec4 g = svoFilterCell(VOLUMES depth, kSvoGatheredFace, c);
  if (g.a <= 0.0f) return vec3(0.0f);
  precise vec3 e = vec3(g) / g.a;
  return e;
}

// One axis of a cubic B-spline sample as two linear ones [Sigg & Hadwiger 2005]: at x (leaf
// units, centres at k + 1/2), the weights w0..w3 of the centres around x pair up as g0 = w0 + w1 at
// q0 (between the first two centres, where linear interpolation weighs them w0 : w1) and
// g1 = w2 + w3 at q1.
struct CubicAxis {
  float q0, q1, g0, g1;
};

VOXGI_FN CubicAxis cubicAxis(float x) {
  precise float s = x - 0.5f;
  precise float i = floor(s);
  precise float a = s - i;
  precise float b = 1.0f - a;
  precise float w0 = (b * b * b) * (1.0f / 6.0f);
  precise float w3 = (a * a * a) * (1.0f / 6.0f);
  precise float w1 = (2.0f / 3.0f) - (a * a) * (1.0f - 0.5f * a);
  precise float w2 = 1.0f - w0 - w1 - w3;
  CubicAxis c;
  c.g0 = w0 + w1;
  c.g1 = w2 + w3;
  c.q0 = (i - 0.5f) + w1 / c.g0;
  c.q1 = (i + 1.5f) + w3 / c.g1;
  return c;
}

// As svoIrradiance, with a cubic B-spline over the 4^3 leaves around p: eight trilinear samples
// (svoFilterCell, one tree walk each) in a fixed order.
VOLUME_FN vec3 svoIrradianceTricubic(VOLUMES_IN vec3 p, int depth) {
  CubicAxis ax = cubicAxis(p.x);
  CubicAxis ay = cubicAxis(p.y);
  CubicAxis az = cubicAxis(p.z);
  precise vec4 g = vec4(0.0f);
  for (int k = 0; k < 8; ++k) {
    vec3 q = vec3((k & 1) == 0 ? ax.q0 : ax.q1, (k & 2) == 0 ? ay.q0 : ay.q1,
                  (k & 4) == 0 ? az.q0 : az.q1);
    precise float w = (((k & 1) == 0 ? ax.g0 : ax.g1) * ((k & 2) == 0 ? ay.g0 : ay.g1)) *
                      ((k & 4) == 0 ? az.g0 : az.g1);
    TrilinearCell c = trilinearCell(0, q, 1 << depth);
    g = g + svoFilterCell(VOLUMES depth, kSvoGatheredFace, c) * w;
  }
  if (g.a <= 0.0f) return vec3(0.0f);
  precise vec3 e = vec3(g) / g.a;
  return e;
}

VOXGI_NAMESPACE_END
#endif
