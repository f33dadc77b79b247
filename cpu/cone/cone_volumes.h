// What the shared cone tracer (shaders/shared/cone/march.h) reads on the CPU, through FETCH:
// pyramid level 0 is the radiance volume, level l >= 1 the pyramid's level l (common/mips.h
// layout, faces side by side along x). Used by the trace_cones and bounce stages and by tests that
// call the kernels directly.
#pragma once

#include <bit>
#include <vector>

#include "common/buffer.h"
#include "common/mips.h"
#include "common/settings.h"
#include "cpu/cone/cell_occupancy.h"
#include "shaders/shared/lighting.h"
#include "shaders/shared/cone/march.h"

namespace voxgi::cpu {

struct ConeVolumes {
  // Level l's first word (level 0: the radiance volume); at most 2^15 voxels a side. Directional
  // levels are copied with the six faces of a voxel next to each other, so the three faces a cone
  // reads share cache lines (the values are the stage buffer's, bit for bit).
  const uint32_t* levels[16] = {};
  std::vector<uint32_t> interleaved;
  CellOccupancy occupancy[16];  // per level
  int faces;
  int n;
  const std::vector<shared::LightData>& lights;
  const std::vector<shared::ConeData>& cones;

  // `pyramid`: radiance_mips or radiance_mips6 of `radiance`, as `mip` asks.
  ConeVolumes(const Buffer& radiance, const Buffer& pyramidBuffer, MipMode mip, int resolution,
              const std::vector<shared::LightData>& l, const std::vector<shared::ConeData>& c)
      : faces(mip == MipMode::anisotropic ? 6 : 1), n(resolution), lights(l), cones(c) {
    const Words& pyramid = pyramidBuffer.words;
    if (faces > 1) interleaved.resize(pyramid.size());
    levels[0] = radiance.words.data();
    occupancy[0] = CellOccupancy(levels[0], n, 4);
    for (int level = 1; level <= mipLevelCount(n); ++level) {
      const size_t offset = 4 * mipLevelOffset(n, level, faces), s = size_t(n >> level);
      if (faces == 1) {
        levels[level] = pyramid.data() + offset;
        occupancy[level] = CellOccupancy(levels[level], int(s), 4);
        continue;
      }
      for (size_t row = 0; row < s * s; ++row)
        for (int face = 0; face < faces; ++face)
          for (size_t x = 0; x < s; ++x)
            for (size_t k = 0; k < 4; ++k)
              interleaved[offset + 4 * ((row * s + x) * size_t(faces) + size_t(face)) + k] =
                  pyramid[offset + 4 * (row * s * size_t(faces) + size_t(face) * s + x) + k];
      levels[level] = interleaved.data() + offset;
      occupancy[level] = CellOccupancy(levels[level], int(s), 4 * faces);
    }
  }
  ConeVolumes(const ConeVolumes&) = delete;

  glm::vec4 pyramidAt(int level, int face, glm::ivec3 v) const {
    const size_t s = size_t(n >> level);
    const size_t voxel = size_t(v.x) + s * (size_t(v.y) + s * size_t(v.z));
    const uint32_t* p =
        levels[level] + 4 * (level == 0 ? voxel : voxel * size_t(faces) + size_t(face));
    return {std::bit_cast<float>(p[0]), std::bit_cast<float>(p[1]), std::bit_cast<float>(p[2]),
            std::bit_cast<float>(p[3])};
  }
  bool cellEmpty(int level, glm::ivec3 i) const { return occupancy[level].empty(i); }
  shared::LightData lightAt(int i) const { return lights[size_t(i)]; }
  shared::ConeData coneAt(int i) const { return cones[size_t(i)]; }
};

}  // namespace voxgi::cpu
