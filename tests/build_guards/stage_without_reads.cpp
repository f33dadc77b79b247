// Must not compile: a stage declared as reading nothing (VOXGI_STAGE's `reads`, common/stages.inc)
// stops the build with a message naming it, as common/stage_list.cpp builds each stage's entry.
#include "common/stage_list.h"

namespace voxgi {
constexpr StageSpec kPlanted = VOXGI_STAGE_SPEC(vct, light_voxels, 0, "planted");
}  // namespace voxgi
