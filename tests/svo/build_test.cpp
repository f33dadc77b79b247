// The sparse voxel octree's structure: Morton keys, the canonical build, neighbour pointers,
// border tiles, brick completion and the brick sampler (docs/svo.md, tests S1-S8).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include <tbb/global_control.h>

#include "common/error.h"
#include "common/svo/canonical.h"
#include "cpu/svo/bricks.h"
#include "shaders/shared/svo/svo_sample.h"

namespace voxgi {
namespace {

using cpu::svo::Octree;
using shared::SvoSample;

SvoSample sampleAt(glm::vec3 p, float r, glm::vec3 albedo = glm::vec3(0.5f),
                   glm::vec3 normal = {0, 1, 0}) {
  SvoSample s{};
  s.position = p;
  s.edge = r;
  s.albedo = albedo;
  s.density = 1.0f / r;
  s.normal = normal;
  return s;
}

// Points on a sphere and a plane through a grid of 2^depth leaves, with RoIs up to one leaf.
std::vector<SvoSample> scatteredSamples(int depth, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float n = float(1 << depth);
  std::vector<SvoSample> out;
  for (size_t i = 0; i < count; ++i) {
    glm::vec3 p;
    if (i % 3 == 0) {
      p = glm::vec3(u(rng) * n, 0.3f * n, u(rng) * n);
    } else {
      const float z = 2.0f * u(rng) - 1.0f, phi = 6.2831853f * u(rng);
      const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
      p = glm::vec3(0.5f * n) + 0.35f * n * glm::vec3(s * std::cos(phi), s * std::sin(phi), z);
    }
    out.push_back(sampleAt(p, 0.25f + 0.75f * u(rng), glm::vec3(u(rng), u(rng), u(rng)),
                           glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) - 0.5f)));
  }
  return out;
}

// The leaves a sample's RoI overlaps, computed independently in double.
std::set<uint64_t> overlappedLeaves(const std::vector<SvoSample>& samples, int depth) {
  const int n = 1 << depth;
  std::set<uint64_t> out;
  for (const SvoSample& s : samples) {
    const double r = s.edge;
    glm::ivec3 lo, hi;
    for (int a = 0; a < 3; ++a) {
      const double p = s.position[a];
      lo[a] = std::max(0, int(std::floor(p - r / 2)));
      hi[a] = std::min(n - 1, int(std::ceil(p + r / 2)) - 1);
    }
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i)
          out.insert(uint64_t(i) + uint64_t(n) * (uint64_t(j) + uint64_t(n) * uint64_t(k)));
  }
  return out;
}

uint32_t word(const Words& w, size_t record, int field, int stride) {
  return w[record * size_t(stride) + size_t(field)];
}

// Node tile t's level and coordinate of its tile.
int tileLevel(const Octree& o, size_t t) {
  return int(word(o.tiles, t, shared::kTileLevel, shared::kTileWords));
}

// ---- S1 Morton keys ----

TEST(SvoMorton, RoundTripsEveryCoordinateUpToDepth6AndRandomOnesAtDepth10) {
  for (uint32_t z = 0; z < 64; ++z)
    for (uint32_t y = 0; y < 64; ++y)
      for (uint32_t x = 0; x < 64; ++x) {
        const glm::uvec3 c(x, y, z);
        ASSERT_EQ(shared::mortonDecode(shared::mortonEncode(c)), c);
      }
  std::mt19937 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const glm::uvec3 c(rng() & 1023u, rng() & 1023u, rng() & 1023u);
    const uint32_t key = shared::mortonEncode(c);
    ASSERT_LT(key, 1u << 30);
    ASSERT_EQ(shared::mortonDecode(key), c);
    // Bit b of each coordinate lands at 3b + axis.
    for (int b = 0; b < 10; ++b)
      for (int a = 0; a < 3; ++a) ASSERT_EQ((key >> (3 * b + a)) & 1u, (c[a] >> b) & 1u);
  }
}

// [Salm 2015, Figure 4.6]: the 2-D keys of the third tree level, row y, column x. With z = 0 the
// 3-D key's bit triples carry (x_b, y_b) in their low two bits.
TEST(SvoMorton, ReproducesTheThesisTwoDimensionalTable) {
  const char* rows[8][8] = {
      {"000000", "000001", "000100", "000101", "010000", "010001", "010100", "010101"},
      {"000010", "000011", "000110", "000111", "010010", "010011", "010110", "010111"},
      {"001000", "001001", "001100", "001101", "011000", "011001", "011100", "011101"},
      {"001010", "001011", "001110", "001111", "011010", "011011", "011110", "011111"},
      {"100000", "100001", "100100", "100101", "110000", "110001", "110100", "110101"},
      {"100010", "100011", "100110", "100111", "110010", "110011", "110110", "110111"},
      {"101000", "101001", "101100", "101101", "111000", "111001", "111100", "111101"},
      {"101010", "101011", "101110", "101111", "111010", "111011", "111110", "111111"}};
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x) {
      const uint32_t key3 = shared::mortonEncode(glm::uvec3(x, y, 0));
      uint32_t key2 = 0;
      for (int b = 0; b < 3; ++b) key2 |= ((key3 >> (3 * b)) & 3u) << (2 * b);
      EXPECT_EQ(key2, std::stoul(rows[y][x], nullptr, 2)) << "x " << x << " y " << y;
    }
}

TEST(SvoMorton, LocalIdsAreTheKeysBitTriplesAndParentsDropOne) {
  const int depth = 7;
  std::mt19937 rng(3);
  for (int i = 0; i < 10000; ++i) {
    const glm::uvec3 leaf(rng() & 127u, rng() & 127u, rng() & 127u);
    const uint32_t key = shared::mortonEncode(leaf);
    for (int l = 1; l <= depth; ++l) {
      const glm::uvec3 node = leaf >> uint32_t(depth - l);
      ASSERT_EQ((key >> (3 * (depth - l))) & 7u, shared::localId(node));
      ASSERT_EQ(key >> (3 * (depth - l)), shared::mortonEncode(node));
    }
  }
}

// ---- S2 build invariants ----

TEST(SvoBuild, LeavesAreTheCellsTheRoisOverlapWithEveryAncestor) {
  const int depth = 5;
  const auto samples = scatteredSamples(depth, 3000, 1);
  const Octree o = cpu::svo::buildOctree(samples, depth);
  const int n = 1 << depth;
  std::set<uint64_t> built;
  for (size_t t = 0; t < o.leafTileCount(); ++t) {
    const uint32_t key = word(o.leafTiles, t, shared::kTileKey, shared::kTileWords);
    const uint32_t parent = word(o.leafTiles, t, shared::kTileParent, shared::kTileWords);
    const uint32_t mask = (o.nodes[parent * shared::kNodeWords + shared::kNodeFlags] >> 8) & 255u;
    const bool border = word(o.leafTiles, t, shared::kTileFlags, shared::kTileWords) != 0;
    EXPECT_EQ(border, mask == 0);
    EXPECT_EQ(o.nodes[parent * shared::kNodeWords + shared::kNodeChild], t);
    for (uint32_t local = 0; local < 8; ++local)
      if ((mask >> local) & 1u) {
        const glm::uvec3 c = shared::mortonDecode((key << 3) | local);
        built.insert(c.x + uint64_t(n) * (c.y + uint64_t(n) * c.z));
      }
  }
  EXPECT_EQ(built, overlappedLeaves(samples, depth));

  // Every real node's parent is real and points at the node's tile; real node tiles at level l
  // are exactly the real nodes of level l - 1.
  for (size_t t = 1; t < o.tileCount(); ++t) {
    const uint32_t parent = word(o.tiles, t, shared::kTileParent, shared::kTileWords);
    ASSERT_NE(parent, shared::kSvoNull);
    EXPECT_EQ(o.nodes[parent * shared::kNodeWords + shared::kNodeChild], t);
    const bool border = word(o.tiles, t, shared::kTileFlags, shared::kTileWords) != 0;
    EXPECT_EQ(border,
              (o.nodes[parent * shared::kNodeWords + shared::kNodeFlags] & shared::kNodeReal) == 0);
    EXPECT_EQ(tileLevel(o, size_t(parent / 8)) + 1, tileLevel(o, t));
  }
  size_t realNodes = 0;
  for (size_t node = 0; node < o.nodes.size() / shared::kNodeWords; ++node) {
    const uint32_t flags = o.nodes[node * shared::kNodeWords + shared::kNodeFlags];
    if ((flags & shared::kNodeReal) == 0) {
      EXPECT_EQ(flags >> 8, 0u) << "an empty slot with real children";
      continue;
    }
    ++realNodes;
    EXPECT_NE(flags >> 8, 0u) << "a real node without a real child";
  }
  size_t realTiles = o.leafTileCount();
  for (size_t t = 1; t < o.tileCount(); ++t)
    realTiles += word(o.tiles, t, shared::kTileFlags, shared::kTileWords) == 0;
  size_t borderLeafTiles = 0;
  for (size_t t = 0; t < o.leafTileCount(); ++t)
    borderLeafTiles += word(o.leafTiles, t, shared::kTileFlags, shared::kTileWords) != 0;
  EXPECT_EQ(realTiles - borderLeafTiles, realNodes);
}

TEST(SvoBuild, StructureDoesNotDependOnSampleOrderOrThreads) {
  const int depth = 6;
  auto samples = scatteredSamples(depth, 4000, 2);
  const Octree reference = cpu::svo::buildOctree(samples, depth);
  const Words referenceSums = cpu::svo::accumulateLeaves(reference, samples, 65536.0f, "test");
  std::mt19937 rng(5);
  for (int i = 0; i < 10; ++i) {
    std::shuffle(samples.begin(), samples.end(), rng);
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, i % 2 ? 1 : 2);
    const Octree o = cpu::svo::buildOctree(samples, depth);
    ASSERT_EQ(o.nodes, reference.nodes);
    ASSERT_EQ(o.tiles, reference.tiles);
    ASSERT_EQ(o.leafTiles, reference.leafTiles);
    ASSERT_EQ(cpu::svo::accumulateLeaves(o, samples, 65536.0f, "test"), referenceSums);
  }
}

// The sums against a plain loop over every sample's eight corners into a map by leaf: samples
// whose RoI crosses a tile's faces add to both tiles.
TEST(SvoBuild, LeafSumsAreEverySampleCornerAddedOnce) {
  const int depth = 5, n = 1 << depth;
  const auto samples = scatteredSamples(depth, 5000, 15);
  const Octree o = cpu::svo::buildOctree(samples, depth);
  const float scale = 4096.0f;
  const Words sums = cpu::svo::accumulateLeaves(o, samples, scale, "test");
  std::map<uint32_t, std::array<int64_t, shared::kSumWords>> expected;
  size_t crossing = 0;
  for (const SvoSample& s : samples) {
    const float r = s.edge;
    const shared::SplatAxis a[3] = {shared::splatAxis(s.position.x, r),
                                    shared::splatAxis(s.position.y, r),
                                    shared::splatAxis(s.position.z, r)};
    std::set<uint32_t> tiles;
    for (int c = 0; c < 8; ++c) {
      const glm::ivec3 corner(c & 1, (c >> 1) & 1, c >> 2);
      glm::ivec3 leaf;
      bool inside = true;
      for (int axis = 0; axis < 3; ++axis) {
        leaf[axis] = a[axis].lo + corner[axis];
        inside = inside && (corner[axis] ? a[axis].w1 : a[axis].w0) > 0.0f && leaf[axis] >= 0 &&
                 leaf[axis] < n;
      }
      if (!inside) continue;
      const float w = shared::splatWeight(a[0], a[1], a[2], s.density, corner);
      auto& v = expected[shared::mortonEncode(glm::uvec3(leaf))];
      v[shared::kSumOpacity] += shared::fixedRound(w, 1.0f, scale);
      for (int ch = 0; ch < 3; ++ch) {
        v[size_t(shared::kSumAlbedo + ch)] += shared::fixedRound(w, s.albedo[ch], scale);
        v[size_t(shared::kSumNormal + ch)] += shared::fixedRound(w, s.normal[ch], scale);
        v[size_t(shared::kSumEmission + ch)] += shared::fixedRound(w, s.emission[ch], scale);
      }
      tiles.insert(shared::mortonEncode(glm::uvec3(leaf >> 1)));
    }
    crossing += tiles.size() > 1;
  }
  EXPECT_GT(crossing, 1000u);  // the case the buckets of neighbouring tiles are for
  size_t checked = 0;
  for (size_t t = 0; t < o.leafTileCount(); ++t) {
    const uint32_t key = word(o.leafTiles, t, shared::kTileKey, shared::kTileWords);
    for (uint32_t local = 0; local < 8; ++local) {
      const auto it = expected.find((key << 3) | local);
      for (int c = 0; c < shared::kSumWords; ++c) {
        const int64_t want = it == expected.end() ? 0 : it->second[size_t(c)];
        ASSERT_EQ(int32_t(sums[(t * 8 + local) * shared::kSumWords + size_t(c)]), want)
            << "leaf tile " << t << " local " << local << " sum " << c;
      }
      checked += it != expected.end();
    }
  }
  EXPECT_EQ(checked, expected.size());
}

TEST(SvoBuild, TilesAreAllocatedLevelByLevelInKeyOrder) {
  const int depth = 5;
  const Octree o = cpu::svo::buildOctree(scatteredSamples(depth, 500, 4), depth);
  ASSERT_GE(o.tileCount(), 1u);
  EXPECT_EQ(tileLevel(o, 0), 1);
  for (size_t t = 1; t < o.tileCount(); ++t) {
    const int l0 = tileLevel(o, t - 1), l1 = tileLevel(o, t);
    ASSERT_TRUE(l1 == l0 || (l1 == l0 + 1 && o.levelStart[size_t(l1)] == t));
    if (l1 == l0) {
      ASSERT_LT(word(o.tiles, t - 1, shared::kTileKey, shared::kTileWords),
                word(o.tiles, t, shared::kTileKey, shared::kTileWords));
    }
  }
  for (size_t t = 1; t < o.leafTileCount(); ++t)
    ASSERT_LT(word(o.leafTiles, t - 1, shared::kTileKey, shared::kTileWords),
              word(o.leafTiles, t, shared::kTileKey, shared::kTileWords));
}

// The canonical form undoes any order of allocation: the CPU build with its tiles shuffled (the
// root tile kept first, as the GPU allocates it) and every reference renumbered comes back as it
// was.
TEST(SvoBuild, CanonicalFormUndoesAnyTileOrder) {
  const int depth = 5;
  const auto samples = scatteredSamples(depth, 2000, 16);
  const Octree o = cpu::svo::buildOctree(samples, depth);
  const Words sums = cpu::svo::accumulateLeaves(o, samples, 4096.0f, "test");
  std::mt19937 rng(17);
  std::vector<uint32_t> nodeTo(o.tileCount()), leafTo(o.leafTileCount());
  std::iota(nodeTo.begin(), nodeTo.end(), 0u);
  std::iota(leafTo.begin(), leafTo.end(), 0u);
  std::shuffle(nodeTo.begin() + 1, nodeTo.end(), rng);
  std::shuffle(leafTo.begin(), leafTo.end(), rng);
  const auto node = [&](uint32_t n) {
    return n == shared::kSvoNull ? n : nodeTo[n / 8] * 8 + n % 8;
  };
  svo::OctreeWords shuffled{Words(o.nodes.size()), Words(o.tiles.size()), Words(o.leafTiles.size()),
                            Words(sums.size())};
  for (size_t t = 0; t < o.tileCount(); ++t) {
    const bool leafParents = tileLevel(o, t) == depth - 1;
    for (size_t w = 0; w < 8 * shared::kNodeWords; ++w) {
      uint32_t v = o.nodes[t * 8 * shared::kNodeWords + w];
      const size_t field = w % shared::kNodeWords;
      if (field == shared::kNodeChild && v != shared::kSvoNull)
        v = leafParents ? leafTo[v] : nodeTo[v];
      if (field >= shared::kNodeNeighbour && field < shared::kNodeFlags) v = node(v);
      shuffled.nodes[size_t(nodeTo[t]) * 8 * shared::kNodeWords + w] = v;
    }
    for (int f = 0; f < shared::kTileWords; ++f) {
      const uint32_t v = o.tiles[t * shared::kTileWords + size_t(f)];
      shuffled.tiles[size_t(nodeTo[t]) * shared::kTileWords + size_t(f)] =
          f == shared::kTileParent ? node(v) : v;
    }
  }
  for (size_t t = 0; t < o.leafTileCount(); ++t) {
    for (int f = 0; f < shared::kTileWords; ++f) {
      const uint32_t v = o.leafTiles[t * shared::kTileWords + size_t(f)];
      shuffled.leafTiles[size_t(leafTo[t]) * shared::kTileWords + size_t(f)] =
          f == shared::kTileParent ? node(v) : v;
    }
    for (size_t w = 0; w < 8 * shared::kSumWords; ++w)
      shuffled.sums[size_t(leafTo[t]) * 8 * shared::kSumWords + w] =
          sums[t * 8 * shared::kSumWords + w];
  }
  ASSERT_NE(shuffled.nodes, o.nodes);
  svo::canonicalize(shuffled, depth);
  EXPECT_EQ(shuffled.nodes, o.nodes);
  EXPECT_EQ(shuffled.tiles, o.tiles);
  EXPECT_EQ(shuffled.leafTiles, o.leafTiles);
  EXPECT_EQ(shuffled.sums, sums);
}

TEST(SvoBuild, NoSampleLeavesTheRootTileAlone) {
  const Octree o = cpu::svo::buildOctree({}, 4);
  EXPECT_EQ(o.tileCount(), 1u);
  EXPECT_EQ(o.leafTileCount(), 0u);
  for (uint32_t n = 0; n < 8; ++n)
    EXPECT_EQ(o.nodes[n * shared::kNodeWords + shared::kNodeChild], shared::kSvoNull);
}

// ---- S3 neighbour pointers, S4 border tiles ----

// Every node slot of every node tile by (level, coordinate).
std::map<std::pair<int, uint32_t>, uint32_t> slotsByKey(const Octree& o) {
  std::map<std::pair<int, uint32_t>, uint32_t> out;
  for (size_t t = 0; t < o.tileCount(); ++t) {
    const uint32_t key = word(o.tiles, t, shared::kTileKey, shared::kTileWords);
    for (uint32_t n = 0; n < 8; ++n) out[{tileLevel(o, t), (key << 3) | n}] = uint32_t(t * 8 + n);
  }
  return out;
}

TEST(SvoBuild, NeighbourPointersAreSymmetricAndExactlyTheExistingSlots) {
  const int depth = 5;
  const Octree o = cpu::svo::buildOctree(scatteredSamples(depth, 2000, 6), depth);
  const auto slots = slotsByKey(o);
  for (const auto& [levelKey, node] : slots) {
    const auto [level, key] = levelKey;
    const glm::ivec3 x(shared::mortonDecode(key));
    for (int f = 0; f < 6; ++f) {
      const uint32_t ptr =
          o.nodes[node * shared::kNodeWords + shared::kNodeNeighbour + uint32_t(f)];
      glm::ivec3 y = x;
      y[f / 2] += f % 2 == 0 ? 1 : -1;
      const bool inside = y[f / 2] >= 0 && y[f / 2] < (1 << level);
      const auto it =
          inside ? slots.find({level, shared::mortonEncode(glm::uvec3(y))}) : slots.end();
      ASSERT_EQ(ptr, it == slots.end() ? shared::kSvoNull : it->second);
      if (ptr != shared::kSvoNull) {  // n.+a.-a = n
        ASSERT_EQ(o.nodes[ptr * shared::kNodeWords + shared::kNodeNeighbour + uint32_t(f ^ 1)],
                  node);
      }
    }
  }
}

// Whether tile `key` exists at `level` (leaf tiles for the depth).
bool tileExists(const Octree& o, int level, glm::ivec3 c) {
  if (c.x < 0 || c.y < 0 || c.z < 0) return false;
  return o.findTile(level, shared::mortonEncode(glm::uvec3(c))) != shared::kSvoNull;
}

TEST(SvoBuild, BorderTilesAreExactlyTheOnesTheRuleRequires) {
  const int depth = 5;
  const Octree o = cpu::svo::buildOctree(scatteredSamples(depth, 1500, 8), depth);
  for (int level = 2; level <= depth; ++level) {
    // Real nodes of the level by coordinate.
    std::set<uint32_t> real;
    const bool leaves = level == depth;
    const size_t count =
        leaves ? o.leafTileCount() : o.levelStart[size_t(level) + 1] - o.levelStart[size_t(level)];
    std::set<uint32_t> required, present;
    for (size_t i = 0; i < count; ++i) {
      const Words& tiles = leaves ? o.leafTiles : o.tiles;
      const size_t t = leaves ? i : o.levelStart[size_t(level)] + i;
      const uint32_t key = word(tiles, t, shared::kTileKey, shared::kTileWords);
      const uint32_t parent = word(tiles, t, shared::kTileParent, shared::kTileWords);
      const uint32_t mask = (o.nodes[parent * shared::kNodeWords + shared::kNodeFlags] >> 8) & 255u;
      present.insert(key);
      if (mask != 0) required.insert(key);
      const glm::ivec3 c(shared::mortonDecode(key));
      for (uint32_t local = 0; local < 8; ++local) {
        if (((mask >> local) & 1u) == 0) continue;
        // Every non-empty set S of axes on which this node is at local coordinate 0.
        for (int s = 1; s < 8; ++s) {
          if ((local & uint32_t(s)) != 0) continue;
          const glm::ivec3 d = c - glm::ivec3(s & 1, (s >> 1) & 1, (s >> 2) & 1);
          if (d.x < 0 || d.y < 0 || d.z < 0) continue;
          ASSERT_TRUE(tileExists(o, level, d)) << "level " << level;
          required.insert(shared::mortonEncode(glm::uvec3(d)));
        }
      }
    }
    EXPECT_EQ(present, required) << "level " << level << ": a tile neither real nor required";
  }
}

// ---- S5 completion, S6 sampling against a dense grid ----

// A value per real node of a level (random; 0 for empty slots and border tiles), as tiles'
// interiors and as a dense grid.
struct LevelValues {
  Words interior;                // 4 floats a voxel, 8 voxels a tile
  std::vector<glm::vec4> dense;  // (2^level)^3, x-fastest
};

LevelValues randomLevelValues(const Octree& o, int level, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const bool leaves = level == o.depth;
  const size_t count =
      leaves ? o.leafTileCount() : o.levelStart[size_t(level) + 1] - o.levelStart[size_t(level)];
  const Words& tiles = leaves ? o.leafTiles : o.tiles;
  const size_t first = leaves ? 0 : o.levelStart[size_t(level)];
  const int n = 1 << level;
  LevelValues v;
  v.interior.resize(count * 8 * 4);
  v.dense.assign(size_t(n) * size_t(n) * size_t(n), glm::vec4(0.0f));
  for (size_t i = 0; i < count; ++i) {
    const uint32_t key = word(tiles, first + i, shared::kTileKey, shared::kTileWords);
    const uint32_t parent = word(tiles, first + i, shared::kTileParent, shared::kTileWords);
    const uint32_t mask =
        level == 1 ? 255u : (o.nodes[parent * shared::kNodeWords + shared::kNodeFlags] >> 8) & 255u;
    for (uint32_t local = 0; local < 8; ++local) {
      if (((mask >> local) & 1u) == 0) continue;
      const glm::vec4 value(u(rng), u(rng), u(rng), u(rng));
      for (int c = 0; c < 4; ++c)
        v.interior[(i * 8 + local) * 4 + size_t(c)] = std::bit_cast<uint32_t>(value[c]);
      const glm::uvec3 x = shared::mortonDecode((key << 3) | local);
      v.dense[x.x + size_t(n) * (x.y + size_t(n) * x.z)] = value;
    }
  }
  return v;
}

// The octree and the completed bricks of one level, as the shared sampler reads them.
struct SvoAccess {
  const Octree& octree;
  const Words& bricks;
  int level;
  uint32_t first;  // the level's first node tile (0 for leaves)
  uint svoNodeWord(uint i) const { return octree.nodes[i]; }
  glm::vec4 svoBrickAt(int, int, uint tile, uint texel) const {
    const size_t at = (size_t(tile - first) * shared::kBrickTexels + texel) * 4;
    return {std::bit_cast<float>(bricks[at]), std::bit_cast<float>(bricks[at + 1]),
            std::bit_cast<float>(bricks[at + 2]), std::bit_cast<float>(bricks[at + 3])};
  }
};

glm::vec4 denseSample(const std::vector<glm::vec4>& dense, int n, const shared::TrilinearCell& c) {
  const auto at = [&](glm::ivec3 v) {
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= n || v.y >= n || v.z >= n) return glm::vec4(0.0f);
    return dense[size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z))];
  };
  const glm::ivec3 b = c.base;
  return shared::blendCell(at(b), at(b + glm::ivec3(1, 0, 0)), at(b + glm::ivec3(0, 1, 0)),
                           at(b + glm::ivec3(1, 1, 0)), at(b + glm::ivec3(0, 0, 1)),
                           at(b + glm::ivec3(1, 0, 1)), at(b + glm::ivec3(0, 1, 1)),
                           at(b + glm::ivec3(1, 1, 1)), c.f);
}

TEST(SvoBricks, CompletionCopiesEachBoundaryTexelFromItsNeighbourTile) {
  const int depth = 5;
  const Octree o = cpu::svo::buildOctree(scatteredSamples(depth, 1500, 9), depth);
  std::mt19937 rng(10);
  for (int level = 1; level <= depth; ++level) {
    const LevelValues v = randomLevelValues(o, level, rng);
    const Words bricks = cpu::svo::completeBricks(o, level, v.interior, 4);
    const bool leaves = level == depth;
    const Words& tiles = leaves ? o.leafTiles : o.tiles;
    const size_t first = leaves ? 0 : o.levelStart[size_t(level)];
    const int n = 1 << level;
    for (size_t i = 0; i < bricks.size() / (27 * 4); ++i) {
      const glm::ivec3 c(
          shared::mortonDecode(word(tiles, first + i, shared::kTileKey, shared::kTileWords)));
      for (int texel = 0; texel < 27; ++texel) {
        const glm::ivec3 t(texel % 3, (texel / 3) % 3, texel / 9);
        const glm::ivec3 x = 2 * c + t;  // the voxel this texel holds
        const bool inside = x.x < n && x.y < n && x.z < n;
        for (int k = 0; k < 4; ++k) {
          const float expected =
              inside ? v.dense[size_t(x.x) + size_t(n) * (size_t(x.y) + size_t(n) * size_t(x.z))][k]
                     : 0.0f;
          ASSERT_EQ(std::bit_cast<float>(bricks[(i * 27 + size_t(texel)) * 4 + size_t(k)]),
                    expected)
              << "level " << level << " tile " << i << " texel " << texel;
        }
      }
    }
  }
}

// The decisive test of the layout: through tiles, bricks, border tiles and completion, the
// sampler gives exactly the dense zero-padded level's trilinear sample, at random points and on
// tile faces, edges, corners and the grid's faces.
TEST(SvoBricks, TrilinearSamplingEqualsTheDenseZeroPaddedLevelOnEveryLevel) {
  const int depth = 6;
  const Octree o = cpu::svo::buildOctree(scatteredSamples(depth, 3000, 11), depth);
  std::mt19937 rng(12);
  const float n = float(1 << depth);
  for (int level = 1; level <= depth; ++level) {
    const LevelValues v = randomLevelValues(o, level, rng);
    const Words bricks = cpu::svo::completeBricks(o, level, v.interior, 4);
    const SvoAccess access{o, bricks, level, level == depth ? 0u : o.levelStart[size_t(level)]};
    const int m = depth - level;  // pyramid level: voxels 2^m leaves wide
    const int side = 1 << level;
    std::uniform_real_distribution<float> u(0.0f, n);
    std::uniform_int_distribution<int> cell(0, side);
    for (int i = 0; i < 100000 / depth; ++i) {
      glm::vec3 p(u(rng), u(rng), u(rng));
      if (i % 4 == 1)  // on voxel centres and faces: tile faces, edges, corners, the grid's faces
        for (int a = 0; a < 3; ++a)
          if (rng() % 2)
            p[a] = std::min(
                n, float(cell(rng)) * float(1 << m) + (rng() % 2 ? 0.5f * float(1 << m) : 0.0f));
      const shared::TrilinearCell c = shared::trilinearCell(m, p, side);
      const glm::vec4 svo = shared::svoFilterCell(access, level, 0, c);
      const glm::vec4 dense = denseSample(v.dense, side, c);
      for (int k = 0; k < 4; ++k)
        ASSERT_EQ(std::bit_cast<uint32_t>(svo[k]), std::bit_cast<uint32_t>(dense[k]))
            << "level " << level << " p (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
  }
}

// ---- S7 RoI splat, S8 premultiplication ----

TEST(SvoSplat, OverlapVolumesSumToTheRoiVolumeAndAreTentWeightsAtOneCell) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0.0f, 30.0f), ur(0.01f, 1.0f);
  for (int i = 0; i < 10000; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    const float r = i % 2 ? 1.0f : ur(rng);
    const shared::SplatAxis x = shared::splatAxis(p.x, r), y = shared::splatAxis(p.y, r),
                            z = shared::splatAxis(p.z, r);
    double sum = 0.0;
    int touched = 0;
    for (int c = 0; c < 8; ++c) {
      const float w = shared::splatWeight(x, y, z, 1.0f, glm::ivec3(c & 1, (c >> 1) & 1, c >> 2));
      sum += w;
      touched += w > 0.0f;
    }
    ASSERT_NEAR(sum, double(r) * r * r, 2e-6 * 30.0) << "r " << r;
    ASSERT_LE(touched, 8);
    if (r == 1.0f)  // tent weights about the cell centres: 1 - |p - centre| per axis
      for (int a = 0; a < 3; ++a) {
        const shared::SplatAxis s = shared::splatAxis(p[a], r);
        const double centre = s.lo + 0.5;
        ASSERT_NEAR(s.w0, 1.0 - std::abs(double(p[a]) - centre), 4e-6);
      }
  }
}

TEST(SvoSplat, SampleAtACellCentreFillsOnlyThatCellAndIntegerShiftsMoveItExactly) {
  const shared::SplatAxis a = shared::splatAxis(5.5f, 1.0f);
  EXPECT_EQ(a.lo, 5);
  EXPECT_EQ(a.w0, 1.0f);
  EXPECT_EQ(a.w1, 0.0f);
  const shared::SplatAxis b = shared::splatAxis(5.3f, 0.5f), c = shared::splatAxis(7.3f, 0.5f);
  EXPECT_EQ(c.lo, b.lo + 2);
  EXPECT_EQ(b.w0, c.w0);
  EXPECT_EQ(b.w1, c.w1);
}

// A cubic lattice of spacing h with r = h (its L-infinity spacing) fills space without overlap:
// every leaf gets h^-3 samples of opacity (1/h) h^3 = h^2 each, 1/h in all.
TEST(SvoSplat, UniformLatticeGivesTheSameOpacityInEveryInteriorLeaf) {
  const int depth = 3;
  const float h = 0.25f;
  std::vector<SvoSample> samples;
  for (float z = 0.125f; z < 8.0f; z += h)
    for (float y = 0.125f; y < 8.0f; y += h)
      for (float x = 0.125f; x < 8.0f; x += h) samples.push_back(sampleAt({x, y, z}, h));
  const Octree o = cpu::svo::buildOctree(samples, depth);
  const Words sums = cpu::svo::accumulateLeaves(o, samples, 65536.0f, "test");
  ASSERT_EQ(o.leafTileCount(), 64u);
  for (size_t v = 0; v < sums.size() / shared::kSumWords; ++v)
    ASSERT_EQ(int32_t(sums[v * shared::kSumWords + shared::kSumOpacity]), 65536 * 4)
        << "leaf " << v;  // 64 samples of (1/h) h^3 = h^2 = 1/16 opacity each: 4
}

TEST(SvoSplat, PremultipliedAlbedoOverOpacityIsTheAlbedoWhateverTheOpacity) {
  const int depth = 4;
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> u(0.0f, 16.0f), ur(0.05f, 1.0f);
  std::vector<SvoSample> samples;
  const glm::vec3 rho(0.7f, 0.25f, 0.5f);
  for (int i = 0; i < 2000; ++i)
    samples.push_back(sampleAt({u(rng), u(rng), u(rng)}, ur(rng), rho));
  const Octree o = cpu::svo::buildOctree(samples, depth);
  const Words sums = cpu::svo::accumulateLeaves(o, samples, 65536.0f, "test");
  for (size_t v = 0; v < sums.size() / shared::kSumWords; ++v) {
    const auto opacity = double(int32_t(sums[v * shared::kSumWords]));
    if (opacity < 64) continue;  // rounding dominates below 2^-10 opacity
    for (int c = 0; c < 3; ++c) {
      const auto albedo =
          double(int32_t(sums[v * shared::kSumWords + shared::kSumAlbedo + size_t(c)]));
      // Each contribution rounds by at most half a unit, on both sums.
      ASSERT_NEAR(albedo / opacity, rho[c], 20.0 * 0.5 / opacity + 1e-6);
    }
  }
}

TEST(SvoSplat, OpacityOverflowIsRefusedNamingTheSource) {
  // 40000 samples of full opacity in one leaf: past 2^31 units.
  std::vector<SvoSample> samples(40000, sampleAt({1.5f, 1.5f, 1.5f}, 1.0f));
  const Octree o = cpu::svo::buildOctree(samples, 2);
  try {
    cpu::svo::accumulateLeaves(o, samples, 65536.0f, "cloud.ply");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cloud.ply: grid.resolution"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxgi
