// What the propagation lanes (cpu/lpv/propagate_lanes.h) need from the rest of the CPU backend:
// volumes moved between the registered buffers' layout (a cell's words together) and the lanes'
// Layout, the face entries in the lanes' form, and the run-time choice of instruction set
// (cpu/simd.h). Shared by the stage (cpu/lpv/propagate.cpp) and its tests.
#pragma once

#include <vector>

#include "cpu/lpv/propagate_lanes.h"
#include "cpu/simd.h"
#include "shaders/shared/lpv/lpv_types.h"

namespace voxgi::cpu::lpv_lanes {

// A volume of `words` floats per cell (cell-major, as the buffers hold it) into `out` in Layout
// (whose pads it leaves as they are), and back.
void toLayout(const Layout& l, int words, const float* cells, float* out);
void fromLayout(const Layout& l, int words, const float* in, float* cells);

// The geometry volume's four blocking coefficients (cell-major, four floats a cell) over rows
// y, z in [-1, n] in Layout, zero outside the grid, as the kernel's blockingAt reads them.
std::vector<float> geometryLayout(const Layout& l, const float* blocking);

// The face entries as the lanes read them; throws std::logic_error for an entry whose lobe is not
// about an axis (every face of the tables is a face of the destination cell).
std::vector<Entry> laneEntries(const std::vector<shared::PropagationEntry>& entries,
                               int coefficients);

// propagateRows* and visibilityRows* of `level`.
void propagateRows(SimdLevel level, const Step& step, int rowBegin, int rowEnd);
void visibilityRows(SimdLevel level, const Step& step, float* visibility, int rowBegin, int rowEnd);

}  // namespace voxgi::cpu::lpv_lanes
