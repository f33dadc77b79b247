// Tie classifiers of the stages that cast a ray per pixel or texel on the CPU and rasterize on the
// GPU: an element whose triangle differs is a tie when a 4-neighbour in the same image picked
// another triangle on the CPU (the element lies on a triangle edge there).
#include "validation/diff.h"

namespace voxgi::validation {
namespace {

// `c`, `g`: primitive ids of images `rows` rows high stacked along y.
TieClassifier edgeTies(const Buffer& c, const Buffer& g, int rows) {
  return [&c, &g, rows](size_t e) {
    const uint32_t mine = c.words[e];
    if (mine == g.words[e]) return false;  // same triangle: the values themselves differ
    const int w = c.extent.x;
    const int x = int(e % size_t(w)), y = int(e / size_t(w));
    const int top = y / rows * rows;
    const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
    for (int i = 0; i < 4; ++i) {
      const int nx = x + dx[i], ny = y + dy[i];
      if (nx < 0 || ny < top || nx >= w || ny >= top + rows) continue;
      if (c.words[size_t(ny) * size_t(w) + size_t(nx)] != mine) return true;
    }
    return false;
  };
}

}  // namespace

TieClassifier gbufferTies(const BufferSet& cpu, const BufferSet& gpu) {
  const Buffer& c = cpu.at(BufferId::common_gbuffer_primitive_id);
  return edgeTies(c, gpu.at(BufferId::common_gbuffer_primitive_id), c.extent.y);
}

TieClassifier rsmTies(const BufferSet& cpu, const BufferSet& gpu) {
  const Buffer& c = cpu.at(BufferId::lpv_rsm_primitive_id);
  return edgeTies(c, gpu.at(BufferId::lpv_rsm_primitive_id), c.extent.x);
}

}  // namespace voxgi::validation
