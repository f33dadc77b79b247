// The cone kernel's pyramidAt through the octree: level 0 the leaves' radiance, level m the six
// faces of tree level depth - m. The includer defines SVO_SOURCE_BINDING and SVO_FACES_BINDING
// and includes svo_tree.glsl first. The light is stored as halves (shared/half_float.h,
// packHalves): an RGBA value is two words.
#include "shared/half_float.h"
layout(std430, binding = SVO_SOURCE_BINDING) readonly buffer Source { uvec2 source[]; };
// six faces per node, by node index
layout(std430, binding = SVO_FACES_BINDING) buffer NodeFaces { uvec2 nodeFaces[]; };

vec4 pyramidAt(int level, int face, ivec3 v) {
  uint s = slotOf(uDepth - level, v);
  if (s == kSvoNull) return vec4(0.0f);
  return unpackHalves(level == 0 ? source[s] : nodeFaces[6u * s + uint(face)]);
}
bool cellEmpty(int level, ivec3 i) { return false; }
