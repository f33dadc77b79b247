// OpenVDB export/import of stage buffers. A volume buffer becomes one grid named after it, with a
// linear transform that puts voxel (i,j,k)'s centre at grid.min + (i+0.5)*h in world space, so the
// grids line up with the scene in any VDB viewer. A pyramid gives one grid per level (and face):
// NAME_L2, NAME_+x_L2, ... with voxel size h*2^level, so every level lines up too. Four components
// give an rgb vector grid plus NAME_alpha. A sparse buffer gives the grids of its SparseLayout.
// Image buffers are not written (they go to EXR). Only
// non-zero voxels are active (background 0). Metadata: voxgi_stage, voxgi_type (u32/i32/f32),
// voxgi_level, voxgi_grid_min, voxgi_grid_size, voxgi_resolution, plus any extra entries given.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/buffer.h"
#include "common/grid.h"
#include "common/sparse_layout.h"

namespace voxgi {

// Throws std::logic_error for a sparse buffer without its layout in `sparse`.
void writeVdb(const std::string& path, const std::vector<const Buffer*>& buffers,
              const GridSpec& grid, const std::map<std::string, std::string>& metadata = {},
              const SparseLayouts& sparse = {});

// Reads every volume grid of 1 or 3 components written by writeVdb back into dense buffers and
// the grid. `specs` supplies the BufferSpec for each grid name (a grid with no spec is skipped).
// Throws InputError on unreadable files or missing metadata.
BufferSet readVdb(const std::string& path, GridSpec& grid,
                  const std::vector<const BufferSpec*>& specs);

}  // namespace voxgi
