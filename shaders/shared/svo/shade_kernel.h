// Indirect diffuse light at a pixel from the octree's leaves [Salm 2015, §4.6]: the light each
// leaf gathered in its last frame (E / pi, premultiplied by the leaf's clamped opacity) sampled
// trilinearly through the leaf bricks and divided by the opacity sampled the same way, so empty
// leaves around the surface do not darken it. Shared by both backends' shade_svo.
#ifndef VOXGI_SVO_SHADE_KERNEL_H
#define VOXGI_SVO_SHADE_KERNEL_H
#include "svo_sample.h"

VOXGI_NAMESPACE_BEGIN

// E / pi at p (leaf units) of a tree of `depth`, from FETCH(svoBrickAt)(depth, 0, leaf tile,
// texel): rgb the premultiplied gathered light, a the opacity.
VOLUME_FN vec3 svoIrradiance(VOLUMES_IN vec3 p, int depth) {
  TrilinearCell c = trilinearCell(0, p, 1 << depth);
  vec4 g = svoFilterCell(VOLUMES depth, 0, c);
  if (g.a <= 0.0f) return vec3(0.0f);
  precise vec3 e = vec3(g) / g.a;
  return e;
}

VOXGI_NAMESPACE_END
#endif
