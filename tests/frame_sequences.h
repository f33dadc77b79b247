// The sequence the incremental-equals-scratch tests run on each technique's "motion" case
// (tests/cases/<technique>.json), on either backend (tests/frame_plan_test.cpp,
// tests/gpu_frame_plan_test.cpp).
#pragma once

#include <vector>

#include "common/pipeline.h"
#include "tests/technique_cases.h"

namespace voxgi::test {

// The mesh with the fewest triangles (but some).
size_t smallestMesh(const Scene& scene);

// Frame 0 the scene; 1 the camera moved; 2 the same; 3 the first light moved; 4 the smallest mesh
// moved (by about a voxel: voxelize updates the frame before's voxels in part); 5 the first mesh
// (the bunny, most of the triangles: a rebuild); 6 the smallest again, by ten voxels (further than
// a block of voxelize's 8^3: the blocks it leaves are resolved again, not only those it reaches).
std::vector<Scene> motionFrames(const Scene& scene);

// Runs the case's motionFrames through FrameRunner on `backend` and expects every frame's
// buffers to equal, word for word, the frame run from scratch on the same backend, and the steps
// to reuse what the change allows: no stage before the first that reads the camera when it alone
// moved, nothing when nothing moved, no voxelization when a light moved.
void expectIncrementalFramesEqualScratch(const TechniqueCase& c, StageBackend& backend);

// The case's motionFrames under update.interval=`interval`: every frame equals, word for word, the
// frame whose volume stages ran from scratch on the scene of the last frame numbered a multiple
// of `interval` and whose other stages ran from scratch on its own; no volume stage runs between.
void expectVolumesUpdateEveryInterval(const TechniqueCase& c, StageBackend& backend, int interval);

// The case's motionFrames at 16^3 under propagate.carry=on (svo): every frame reached incrementally
// equals, word for word, the frame a runner reached from scratch (which carries the same light: the
// carry is an input, not a cache), and propagate runs in every frame, nothing having moved or not.
void expectCarriedFramesEqualScratch(TechniqueCase c, StageBackend& backend);

// vct's light_voxels relighting in part: a lit floor and, in a mesh of its own, a blocker that
// moves by two voxels, so that its shadow moves on floor voxels outside the changed box. Expects
// the frame reached incrementally to equal the frame from scratch, and the stage run on a frame
// before whose radiance is poisoned (-1) to keep the poison only in voxels whose radiance is the
// same in both frames from scratch, to keep it in some floor voxels, and to relight every floor
// voxel the shadow moved on.
void expectPartialRelightEqualsScratch(StageBackend& backend);

}  // namespace voxgi::test
