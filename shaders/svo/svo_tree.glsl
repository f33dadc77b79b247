// The octree's node words as every GPU pass over the tree reads them (binding 0), and the value
// slot of a voxel of any level, found by walking down from the root tile (svo_layout.h).
layout(std430, binding = 0) readonly buffer Nodes { uint nodes[]; };
uniform int uDepth;

uint svoNodeWord(uint i) { return nodes[i]; }
#include "shared/svo/svo_layout.h"

// The value slot of voxel v of tree `level`: node index (node levels) or leaf slot; kSvoNull if
// its tile does not exist.
uint slotOf(int level, ivec3 v) {
  uint t = svoFindTile(level, uvec3(v >> 1));
  return t == kSvoNull ? kSvoNull : t * 8u + localId(uvec3(v));
}
