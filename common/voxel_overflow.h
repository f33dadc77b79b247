// The check, before voxelize runs, for triangles repeated so often that their copies overflow the
// fixed-point sums of a voxel (more than 32768 voxel faces of surface in one voxel, see
// shaders/shared/voxelize_layout.h). Both backends also detect the overflow while they accumulate,
// but a scene exported with every triangle a million times would take minutes to get there: this
// finds the repeated copies in one pass and refuses the scene at once.
#pragma once

#include <string>

#include "common/voxel_triangles.h"

namespace voxgi {

// Throws InputError(file, "meshes", ...) when identical copies of one triangle put more than
// kMaxWeightSum into one voxel of an n^3 grid in the given mode.
void refuseRepeatedTriangles(const VoxelTriangles& triangles, int n, bool antialiased,
                             const std::string& file);

}  // namespace voxgi
