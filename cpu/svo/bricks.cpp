#include "cpu/svo/bricks.h"

#include <algorithm>

#include "common/parallel.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::cpu::svo {

template <class Out>
Out completeBricks(const Octree& octree, int level,
                   std::span<const typename Out::value_type> interior, int components) {
  using namespace shared;
  const bool leaves = level == octree.depth;
  const Words& tiles = leaves ? octree.leafTiles : octree.tiles;
  const size_t first = leaves ? 0 : octree.levelStart[size_t(level)];
  const size_t count =
      leaves ? octree.leafTileCount()
             : octree.levelStart[size_t(level) + 1] - octree.levelStart[size_t(level)];
  const auto c = size_t(components);
  Out bricks(count * kBrickTexels * c);  // value-initialized: texels without a source stay 0
  parallelFor(size_t(0), count, [&](size_t t) {
    const uint32_t parent = tiles[(first + t) * kTileWords + kTileParent];
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          // The tile whose interior holds this texel: this one, or the one the chain of + faces
          // of the parent's neighbours leads to for each coordinate 2.
          size_t source = t;
          if (i == 2 || j == 2 || k == 2) {
            uint32_t node = parent;
            const int on[3] = {i, j, k};
            for (int a = 0; a < 3 && node != kSvoNull; ++a)
              if (on[a] == 2)
                node = octree.nodes[size_t(node) * kNodeWords + kNodeNeighbour + size_t(2 * a)];
            const uint32_t child =
                node == kSvoNull ? kSvoNull : octree.nodes[size_t(node) * kNodeWords + kNodeChild];
            if (child == kSvoNull) continue;  // the texel stays 0
            source = child - first;
          }
          const uint32_t local =
              localId(glm::uvec3(uint32_t(i % 2), uint32_t(j % 2), uint32_t(k % 2)));
          const size_t from = (source * 8 + local) * c;
          const size_t to = (t * kBrickTexels + brickTexel(glm::ivec3(i, j, k))) * c;
          std::copy_n(interior.begin() + ptrdiff_t(from), c, bricks.begin() + ptrdiff_t(to));
        }
  });
  return bricks;
}

template Words completeBricks<Words>(const Octree&, int, std::span<const uint32_t>, int);
template std::vector<glm::vec4> completeBricks<std::vector<glm::vec4>>(const Octree&, int,
                                                                       std::span<const glm::vec4>,
                                                                       int);

}  // namespace voxgi::cpu::svo
