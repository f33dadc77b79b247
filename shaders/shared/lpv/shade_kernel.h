// shade_lpv's arithmetic: irradiance at a surface point from the accumulated volume
// [Martin 2012, §3.2.4; Kaplanyan & Dachsbacher 2010]: E = (1 / s^2) sum_i c_i(x) A_l Y_i(-n),
// with c trilinear between cell centres. The lobe is about -n (light flowing into the surface;
// Martin's Eq. 3.4 writes +n) and 1 / s^2 turns a cell's radiant intensity into radiance (Eq. 3.4
// omits it, so its result depends on the cell size): docs/lpv.md.
//
// Reads FETCH(accumulatedAt)(cell, word) -> float, 0 outside the grid.
#ifndef VOXGI_LPV_SHADE_KERNEL_H
#define VOXGI_LPV_SHADE_KERNEL_H
#include "lpv_types.h"
#include "sh.h"

VOXGI_NAMESPACE_BEGIN

// Irradiance / pi at `position` (voxel-local) on a surface of unit normal `normal`, sampled
// p.scale.y cells along the normal (shade.offset: away from the surface's own cell, whose light
// and blockers it shares).
VOLUME_FN vec3 lpvIrradiance(VOLUMES_IN vec3 position, vec3 normal, ShadeParams p) {
  int coefficients = p.shape.y;
  float lobe[9];
  for (int i = 0; i < coefficients; ++i) lobe[i] = shCosineLobe(i, -normal);
  // shade.offset cells along the normal, then cell centres at i + 1/2
  precise vec3 t = (position + normal * p.scale.y) - vec3(0.5f);
  ivec3 base = ivec3(floor(t));
  precise vec3 f = t - vec3(base);
  precise vec3 sum = vec3(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 bit = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    precise float wx = bit.x == 1 ? f.x : 1.0f - f.x, wy = bit.y == 1 ? f.y : 1.0f - f.y,
                  wz = bit.z == 1 ? f.z : 1.0f - f.z;
    precise float weight = wx * wy * wz;
    if (weight == 0.0f) continue;
    ivec3 cell = base + bit;
    precise vec3 e = vec3(0.0f);
    for (int c = 0; c < 3; ++c) {
      precise float dotted = 0.0f;
      for (int i = 0; i < coefficients; ++i)
        dotted = dotted + FETCH(accumulatedAt)(cell, c * coefficients + i) * lobe[i];
      e[c] = dotted;
    }
    sum = sum + e * weight;
  }
  precise vec3 irradiance = sum * p.scale.x;
  return irradiance * 0.318309886f;  // / pi
}

VOXGI_NAMESPACE_END
#endif
