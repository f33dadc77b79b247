#include "common/io/buffer_io.h"

#include "common/io/vdb_io.h"

namespace voxgi {

Image bufferImage(const Buffer& b) {
  Image image(b.extent.x, b.extent.y);
  for (size_t e = 0; e < b.elementCount(); ++e)
    for (int c = 0; c < 3; ++c) {
      const int from = b.components() == 1 ? 0 : c;
      image.pixels[e][c] = from < b.components() ? static_cast<float>(b.value(e, from)) : 0.0f;
    }
  return image;
}

std::vector<std::string> writeBuffers(const std::string& prefix,
                                      const std::vector<const Buffer*>& buffers,
                                      const GridSpec& grid,
                                      const std::map<std::string, std::string>& metadata,
                                      const SparseLayouts& sparse) {
  std::vector<std::string> written;
  std::vector<const Buffer*> voxels;
  for (const Buffer* b : buffers) {
    if (b->spec->shape != BufferShape::image && b->spec->shape != BufferShape::maps) {
      voxels.push_back(b);
      continue;
    }
    const std::string path = prefix + "." + std::string(b->spec->name) + ".exr";
    writeExr(path, bufferImage(*b));
    written.push_back(path);
  }
  if (!voxels.empty()) {
    writeVdb(prefix + ".vdb", voxels, grid, metadata, sparse);
    written.push_back(prefix + ".vdb");
  }
  return written;
}

}  // namespace voxgi
