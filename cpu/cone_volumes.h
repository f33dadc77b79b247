// What the shared cone tracer (shaders/shared/cone_kernel.h) reads on the CPU, through FETCH:
// pyramid level 0 is the radiance volume, level l >= 1 the pyramid's level l (common/mips.h
// layout, faces side by side along x). Used by the trace_cones stage and by tests that call the
// kernel directly.
#pragma once

#include <bit>
#include <vector>

#include "common/buffer.h"
#include "common/mips.h"
#include "common/settings.h"
#include "shaders/shared/cone_kernel.h"

namespace voxgi::cpu {

struct ConeVolumes {
  const uint32_t* radiance;
  const uint32_t* pyramid;           // null for a 1^3 grid
  std::vector<size_t> levelOffsets;  // element offset of each level in `pyramid`
  int n;
  int faces;
  const std::vector<shared::LightData>& lights;
  const std::vector<shared::ConeData>& cones;

  // `buffers` holds radiance and the pyramid `mip` asks for.
  ConeVolumes(const BufferSet& buffers, MipMode mip, int resolution,
              const std::vector<shared::LightData>& l, const std::vector<shared::ConeData>& c)
      : radiance(buffers.at("radiance").words.data()),
        pyramid(buffers.at(mip == MipMode::anisotropic ? "radiance_mips6" : "radiance_mips")
                    .words.data()),
        n(resolution),
        faces(mip == MipMode::anisotropic ? 6 : 1),
        lights(l),
        cones(c) {
    for (int level = 0; level <= mipLevelCount(n); ++level)
      levelOffsets.push_back(level == 0 ? 0 : size_t(mipLevelOffset(n, level, faces)));
  }

  static glm::vec4 load(const uint32_t* p) {
    return {std::bit_cast<float>(p[0]), std::bit_cast<float>(p[1]), std::bit_cast<float>(p[2]),
            std::bit_cast<float>(p[3])};
  }
  glm::vec4 pyramidAt(int level, int face, glm::ivec3 v) const {
    if (level == 0)
      return load(radiance +
                  4 * (size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z))));
    const int s = n >> level;
    const size_t x = size_t(face * s + v.x), width = size_t(faces * s);
    return load(pyramid + 4 * (levelOffsets[size_t(level)] + x +
                               width * (size_t(v.y) + size_t(s) * size_t(v.z))));
  }
  shared::LightData lightAt(int i) const { return lights[size_t(i)]; }
  shared::ConeData coneAt(int i) const { return cones[size_t(i)]; }
};

}  // namespace voxgi::cpu
