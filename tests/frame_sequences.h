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
// (the bunny, most of the triangles: a rebuild); 6 the smallest again.
std::vector<Scene> motionFrames(const Scene& scene);

// Runs the case's motionFrames through FrameRunner on `backend` and expects every frame's
// buffers to equal, word for word, the frame run from scratch on the same backend, and the steps
// to reuse what the change allows: no stage before the first that reads the camera when it alone
// moved, nothing when nothing moved, no voxelization when a light moved.
void expectIncrementalFramesEqualScratch(const TechniqueCase& c, StageBackend& backend);

}  // namespace voxgi::test
