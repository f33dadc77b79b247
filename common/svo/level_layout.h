// Where the octree's sparse buffers lie as OpenVDB grids (common/io/vdb_io.h, docs/svo.md "Dumps"):
// leaves at pyramid level 0 on the scene's grid, node level l at pyramid level depth - l, each
// voxel at its Morton key's coordinate, so every level lines up with the dense grids in a viewer.
#pragma once

#include "common/buffer.h"
#include "common/grid.h"
#include "common/sparse_layout.h"

namespace voxgi::svo {

// The layout of every sparse buffer in `run` (a run of the svo technique over `grid`; none if
// build's buffers are not in it).
SparseLayouts sparseLayouts(const BufferSet& run, const GridSpec& grid);

}  // namespace voxgi::svo
