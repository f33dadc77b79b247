// The first mip step's optional weighting of a leaf per face ([Salm 2015, §4.4.2]; docs/svo.md):
// (1 - n.f) / 2 for the leaf's mean normal n and the face's travel direction f, so a surface is
// seen from the side its normal faces. Shared by both backends' mip. Included by C++ and GLSL.
#ifndef VOXGI_SVO_MIP_WEIGHTS_H
#define VOXGI_SVO_MIP_WEIGHTS_H
#include "../vector_math.h"

VOXGI_NAMESPACE_BEGIN

// `value` weighted for face `face` (+x -x +y -y +z -z) by its normal sum `ndf`; a leaf whose
// normals cancel keeps its value.
VOXGI_FN vec4 ndfWeighted(vec4 value, vec3 ndf, int face) {
  if (ndf == vec3(0.0f)) return value;
  vec3 n = normalize3(ndf);
  precise float along = face % 2 == 0 ? n[face / 2] : -n[face / 2];
  precise float w = (1.0f - along) * 0.5f;
  precise vec4 weighted = value * w;
  return weighted;
}

VOXGI_NAMESPACE_END
#endif
