// Pyramids on the CPU (cpu/vct/pyramid.h): the isotropic shared kernel per voxel, the directional
// one unrolled over rows. Every voxel is written by one task, so any thread count gives the same
// bits.
#include "common/parallel.h"
#include "cpu/vct/pyramid.h"

#include <tbb/blocked_range.h>

#include "common/mips.h"
#include "shaders/shared/cone/mip.h"

namespace voxgi::cpu {
namespace {

// Isotropic children from the level below (the radiance volume or the previous level), a
// `size`^3 volume.
struct Children {
  const uint32_t* words;
  int size;
  glm::vec4 childAt(int, glm::ivec3 c) const {
    const size_t e = size_t(c.x) + size_t(size) * (size_t(c.y) + size_t(size) * size_t(c.z));
    const uint32_t* p = words + 4 * e;
    return {std::bit_cast<float>(p[0]), std::bit_cast<float>(p[1]), std::bit_cast<float>(p[2]),
            std::bit_cast<float>(p[3])};
  }
};

// The 4 (near, far) child pairs of a directional face in shared::mipAnisotropic's (j, i) order;
// child = dx + 2 dy + 4 dz.
struct FacePairs {
  int near[4], far[4];
};
constexpr FacePairs facePairs(int face) {
  const int axis = face / 2;
  const bool positive = face % 2 == 0;
  const int step = 1 << axis;       // the child one step along the face's axis
  const int u = axis == 0 ? 2 : 1;  // first axis across: y for x, else x
  const int w = axis == 2 ? 2 : 4;  // second axis across: y for z, else z
  FacePairs p{};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int lo = u * i + w * j;
      p.near[2 * j + i] = positive ? lo : lo + step;
      p.far[2 * j + i] = positive ? lo + step : lo;
    }
  return p;
}

// One directional face of a parent voxel from its 8 children: shared::mipAnisotropic's
// operations in its order (so the same bits), with the children's indices known at compile time.
template <int Face>
inline void compositeFace(const float (&children)[8][4], uint32_t* out) {
  constexpr FacePairs pairs = facePairs(Face);
  float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (int q = 0; q < 4; ++q) {
    const float* near = children[pairs.near[q]];
    const float* far = children[pairs.far[q]];
    const float transparency = 1.0f - near[3];
    for (int k = 0; k < 4; ++k) sum[k] = sum[k] + (near[k] + far[k] * transparency);
  }
  for (int k = 0; k < 4; ++k) out[k] = std::bit_cast<uint32_t>(sum[k] * 0.25f);
}

// The directional faces of one level over raw rows. Level 1 reads the radiance volume, whose 8
// children every face shares, so each parent voxel loads them once for all six faces
// (tests/vct/mip_test.cpp checks the bits against the shared kernel).
void anisotropicLevel(const uint32_t* src, int srcSize, bool fromBase, uint32_t* dst, int s) {
  const size_t srcWidth = size_t(srcSize) * (fromBase ? 1 : shared::kFaces);
  const size_t dstWidth = size_t(s) * shared::kFaces;
  parallelFor(tbb::blocked_range<int>(0, s * s), [&](const auto& rows) {
    for (int row = rows.begin(); row != rows.end(); ++row) {
      const size_t y = size_t(row % s), z = size_t(row / s);
      // Child rows (dy, dz) of this parent row; face f's children lie f * srcSize voxels on.
      const uint32_t* childRows[4];
      for (size_t k = 0; k < 4; ++k)
        childRows[k] =
            src + 4 * srcWidth * ((2 * y + (k & 1)) + size_t(srcSize) * (2 * z + (k >> 1)));
      uint32_t* out = dst + 4 * dstWidth * size_t(row);
      for (size_t x = 0; x < size_t(s); ++x) {
        float children[8][4];
        const auto load = [&](int face) {
          const size_t offset = size_t(face) * size_t(srcSize) + 2 * x;
          for (int c = 0; c < 8; ++c) {
            const uint32_t* p = childRows[c >> 1] + 4 * (offset + size_t(c & 1));
            for (int k = 0; k < 4; ++k) children[c][k] = std::bit_cast<float>(p[k]);
          }
        };
        const auto face = [&]<int F>() {
          if (F == 0 || !fromBase) load(fromBase ? 0 : F);
          compositeFace<F>(children, out + 4 * (size_t(F) * size_t(s) + x));
        };
        face.template operator()<0>();
        face.template operator()<1>();
        face.template operator()<2>();
        face.template operator()<3>();
        face.template operator()<4>();
        face.template operator()<5>();
      }
    }
  });
}

}  // namespace

void buildPyramid(const BufferSpec& spec, const Buffer& radiance, int n, Buffer& out) {
  const int faces = spec.shape == BufferShape::mips6 ? shared::kFaces : 1;
  const glm::ivec3 extent = shapeExtent(spec.shape, n, {});
  if (out.spec != &spec || out.extent != extent) out = Buffer(spec, extent);
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const int s = n >> level;
    uint32_t* dst = out.words.data() + 4 * mipLevelOffset(n, level, faces);
    if (faces == shared::kFaces) {
      const uint32_t* src = level == 1 ? radiance.words.data()
                                       : out.words.data() + 4 * mipLevelOffset(n, level - 1, faces);
      anisotropicLevel(src, 2 * s, level == 1, dst, s);
      continue;
    }
    const Children children{
        level == 1 ? radiance.words.data() : out.words.data() + 4 * mipLevelOffset(n, level - 1, 1),
        2 * s};
    parallelFor(tbb::blocked_range<int>(0, s * s), [&](const auto& rows) {
      for (int row = rows.begin(); row != rows.end(); ++row)
        for (int x = 0; x < s; ++x) {
          const glm::vec4 r = shared::mipIsotropic(children, glm::ivec3(x, row % s, row / s));
          uint32_t* p = dst + 4 * (size_t(x) + size_t(s) * size_t(row));
          for (int c = 0; c < 4; ++c) p[c] = std::bit_cast<uint32_t>(r[c]);
        }
    });
  }
}

}  // namespace voxgi::cpu
