// Writing any stage's buffers for inspection: volumes and pyramids into one OpenVDB file,
// image buffers as one EXR each.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/buffer.h"
#include "common/grid.h"
#include "common/io/image_io.h"
#include "common/io/vdb_io.h"

namespace voxgi {

// An image buffer as RGB: 1 component is grey, 2 or more give the first three (zero-filled);
// integers (ids) become their float value.
Image bufferImage(const Buffer& b);

// Writes `<prefix>.vdb` (if there are voxel or sparse buffers, the latter placed by `sparse`) and
// `<prefix>.<buffer>.exr` per image buffer; returns the paths written.
std::vector<std::string> writeBuffers(const std::string& prefix,
                                      const std::vector<const Buffer*>& buffers,
                                      const GridSpec& grid,
                                      const std::map<std::string, std::string>& metadata = {},
                                      const SparseLayouts& sparse = {});

}  // namespace voxgi
