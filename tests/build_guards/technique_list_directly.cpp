// Must not compile (tests/CMakeLists.txt): a technique's list is only read through
// common/stages.inc, which checks the macros.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/vct/stages.inc"
