// Must not compile (tests/CMakeLists.txt): the stage list undefines its macros, so a second
// include without defining them again fails.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/stages.inc"
#include "common/stages.inc"
