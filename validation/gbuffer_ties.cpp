#include "validation/diff.h"

namespace voxgi::validation {

TieClassifier gbufferTies(const BufferSet& cpu, const BufferSet& gpu) {
  const Buffer& c = cpu.at(BufferId::common_gbuffer_primitive_id);
  const Buffer& g = gpu.at(BufferId::common_gbuffer_primitive_id);
  return [&c, &g](size_t e) {
    const uint32_t mine = c.words[e];
    if (mine == g.words[e]) return false;  // same triangle: the values themselves differ
    const int w = c.extent.x, h = c.extent.y;
    const int x = int(e % size_t(w)), y = int(e / size_t(w));
    const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
    for (int i = 0; i < 4; ++i) {
      const int nx = x + dx[i], ny = y + dy[i];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      if (c.words[size_t(ny) * size_t(w) + size_t(nx)] != mine) return true;
    }
    return false;
  };
}

}  // namespace voxgi::validation
