// Must not compile (tests/CMakeLists.txt): the stage list included with one macro missing fails
// instead of expanding to nothing.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#include "common/stages.inc"
