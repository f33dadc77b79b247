// CPU mip stage: each pyramid level from the one below with the shared kernel
// (shaders/shared/mip_kernel.h); every voxel is written by one task, so any thread count gives the
// same bits.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/mips.h"
#include "cpu/pyramid.h"
#include "cpu/stages.h"
#include "shaders/shared/mip_kernel.h"

namespace voxgi::cpu {
namespace {

// Reads children from the level below: the radiance volume (faces == 0: shared by every face)
// or the previous pyramid level (`faces` volumes of `size`^3 side by side along x).
struct Children {
  const uint32_t* words;
  int size;
  int faces;
  glm::vec4 childAt(int face, glm::ivec3 c) const {
    const int x = faces == 0 ? c.x : c.x + face * size;
    const int width = faces == 0 ? size : faces * size;
    const size_t e = size_t(x) + size_t(width) * (size_t(c.y) + size_t(size) * size_t(c.z));
    const uint32_t* p = words + 4 * e;
    return {std::bit_cast<float>(p[0]), std::bit_cast<float>(p[1]), std::bit_cast<float>(p[2]),
            std::bit_cast<float>(p[3])};
  }
};

}  // namespace

Buffer buildPyramid(const BufferSpec& spec, const Buffer& radiance, int n, int faces) {
  Buffer out(spec, shapeExtent(spec.shape, n, {}));
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const int s = n >> level;
    const Children children =
        level == 1
            ? Children{radiance.words.data(), n, 0}
            : Children{out.words.data() + 4 * mipLevelOffset(n, level - 1, faces), 2 * s, faces};
    uint32_t* dst = out.words.data() + 4 * mipLevelOffset(n, level, faces);
    const int width = faces * s;
    tbb::parallel_for(tbb::blocked_range<int>(0, s * s), [&](const auto& rows) {
      for (int row = rows.begin(); row != rows.end(); ++row)
        for (int x = 0; x < width; ++x) {
          const glm::ivec3 v(x % s, row % s, row / s);
          const int face = x / s;
          const glm::vec4 r = faces == 1 ? shared::mipIsotropic(children, v)
                                         : shared::mipAnisotropic(children, v, face);
          uint32_t* p = dst + 4 * (size_t(x) + size_t(width) * size_t(row));
          for (int c = 0; c < 4; ++c) p[c] = std::bit_cast<uint32_t>(r[c]);
        }
    });
  }
  return out;
}

void mip(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, "mip");
  const char* name = pyramidName(ctx.plan.mip);
  buffers[name] = buildPyramid(bufferSpec("mip", name), buffers.at("radiance"),
                               ctx.scene.grid.resolution, pyramidFaces(ctx.plan.mip));
}

}  // namespace voxgi::cpu
