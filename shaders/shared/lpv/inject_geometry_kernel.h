// inject_geometry's arithmetic: the geometry volume's blocking potential from voxelize's surface
// sums [Kaplanyan & Dachsbacher 2010, §5; Martin 2012, §3.2.2]. A surface of area A and normal n
// blocks B(w) = (A / s^2) max(0, n . w) of a cell's cross-section toward w; its 2-band SH is
// (A / s^2) (pi Y_0, 2 pi / 3 Y_1m(n)), linear in A n, so the sums of voxelize (area, and area x
// unit normal) give the 2-band lobe of all a voxel's surfaces exactly. The geometry volume's cell
// g is centred on the upper corner of LPV cell g, and overlaps an eighth of each of the 8 voxels
// around that corner: each lends it an eighth of its surface.
//
// With inject_geometry.blockers=rsm the surfaces come from the RSM texels instead [Martin 2012,
// §3.2.2]: each texel's true area and normal in fixed point, at the corner nearest its hit
// (rsmBlocker in rsm_kernel.h).
#ifndef VOXGI_LPV_INJECT_GEOMETRY_KERNEL_H
#define VOXGI_LPV_INJECT_GEOMETRY_KERNEL_H
#include "../voxelize_layout.h"
#include "rsm_kernel.h"
#include "sh.h"

VOXGI_NAMESPACE_BEGIN

// A_0 K0 and A_1 K1 as literals: a product of two constants may be folded in another precision
// by a GLSL compiler.
const float kShLobe0 = 0.886226925452758f;  // pi / (2 sqrt(pi)) = sqrt(pi) / 2
const float kShLobe1 = 1.023326707946489f;  // (2 pi / 3) sqrt(3) / (2 sqrt(pi)) = sqrt(pi / 3)

// The 2-band blocking lobe of surfaces of total area s.x (cells^2) and area-weighted normal s.yzw.
VOXGI_FN vec4 blockingLobe(vec4 s) {
  return vec4(kShLobe0 * s.x, -kShLobe1 * s.z, kShLobe1 * s.w, -kShLobe1 * s.y);
}

// The blocking potential of GV cell g: reads FETCH(surfaceAt)(v) -> vec4(weight_sum, normal_sum)
// as floats (0 outside the grid).
VOLUME_FN vec4 cornerBlocking(VOLUMES_IN ivec3 g) {
  precise vec4 sum = vec4(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 v = g + ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    sum = sum + FETCH(surfaceAt)(v);
  }
  // area and area-weighted normal in cell faces (s^2), an eighth of the 8 voxels' sums
  precise vec4 s = sum * (0.125f / kWeightScale);
  return blockingLobe(s);
}

// The blocking potential of a GV cell from its RSM blocker sum (as floats, kBlockerScale units).
VOXGI_FN vec4 rsmBlocking(vec4 sum) {
  precise vec4 s = sum * (1.0f / kBlockerScale);
  return blockingLobe(s);
}

VOXGI_NAMESPACE_END
#endif
