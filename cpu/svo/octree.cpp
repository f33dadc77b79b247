#include "cpu/svo/octree.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/memory.h"
#include "common/parallel.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::cpu::svo {
namespace {

using shared::kNodeWords;
using shared::kSvoNull;
using shared::kTileWords;

// The tiles of one level, sorted by key: which nodes of each hold samples, and whether it is a
// border tile.
struct LevelTiles {
  std::vector<uint32_t> keys;
  std::vector<uint8_t> masks;
  std::vector<uint8_t> border;
};

// f(leaf, weight) for every leaf of a grid n leaves a side whose cell the sample's RoI overlaps.
template <class F>
void forEachLeaf(const shared::SvoSample& s, int n, const F& f) {
  const glm::vec3 p(s.position);
  if (!shared::splatInDomain(p, float(n))) return;
  const float r = s.position.w;
  const shared::SplatAxis ax = shared::splatAxis(p.x, r), ay = shared::splatAxis(p.y, r),
                          az = shared::splatAxis(p.z, r);
  for (int cz = 0; cz < 2; ++cz) {
    const int k = az.lo + cz;
    if ((cz == 0 ? az.w0 : az.w1) <= 0.0f || k < 0 || k >= n) continue;
    for (int cy = 0; cy < 2; ++cy) {
      const int j = ay.lo + cy;
      if ((cy == 0 ? ay.w0 : ay.w1) <= 0.0f || j < 0 || j >= n) continue;
      for (int cx = 0; cx < 2; ++cx) {
        const int i = ax.lo + cx;
        if ((cx == 0 ? ax.w0 : ax.w1) <= 0.0f || i < 0 || i >= n) continue;
        f(glm::ivec3(i, j, k), shared::splatWeight(ax, ay, az, s.albedo.w, glm::ivec3(cx, cy, cz)));
      }
    }
  }
}

// The leaf tiles the samples touch, with their leaf masks: one byte per possible leaf tile,
// marked in parallel, then read in key order (which is Morton order).
LevelTiles markLeafTiles(std::span<const shared::SvoSample> samples, int depth) {
  std::vector<uint8_t> marks(size_t(1) << (3 * (depth - 1)));
  parallelFor(tbb::blocked_range<size_t>(0, samples.size(), 4096),
              [&](const tbb::blocked_range<size_t>& range) {
                for (size_t i = range.begin(); i != range.end(); ++i)
                  forEachLeaf(samples[i], 1 << depth, [&](glm::ivec3 leaf, float) {
                    const uint32_t key = shared::mortonEncode(glm::uvec3(leaf));
                    std::atomic_ref<uint8_t>(marks[key >> 3])
                        .fetch_or(uint8_t(1u << (key & 7u)), std::memory_order_relaxed);
                  });
              });
  LevelTiles out;
  for (size_t k = 0; k < marks.size(); k += 8) {
    uint64_t word;
    std::memcpy(&word, &marks[k], sizeof word);
    if (word == 0) continue;
    for (size_t j = k; j < k + 8; ++j)
      if (marks[j] != 0) {
        out.keys.push_back(uint32_t(j));
        out.masks.push_back(marks[j]);
      }
  }
  out.border.assign(out.keys.size(), 0);
  return out;
}

// The real tiles one level up: the parents of `below`'s tiles, grouped by tile.
LevelTiles parentTiles(const LevelTiles& below) {
  LevelTiles out;
  for (size_t i = 0; i < below.keys.size(); ++i) {
    if (below.border[i]) continue;
    const uint32_t key = below.keys[i] >> 3;
    if (out.keys.empty() || out.keys.back() != key) {
      out.keys.push_back(key);
      out.masks.push_back(0);
    }
    out.masks.back() = uint8_t(out.masks.back() | (1u << (below.keys[i] & 7u)));
  }
  out.border.assign(out.keys.size(), 0);
  return out;
}

// Adds the border tiles of a level (docs/svo.md): tile T needs the tile T - sum of e_a over a
// non-empty axis set S when one of its real nodes has local coordinate 0 on every axis of S, so
// that the neighbour's brick boundary holds that node's voxel. Tiles left of the grid are not
// needed (the sampler reads 0 there).
void addBorderTiles(LevelTiles& level) {
  uint8_t needs[8] = {};
  for (uint32_t s = 1; s < 8; ++s)
    for (uint32_t n = 0; n < 8; ++n)
      if ((n & s) == 0) needs[s] = uint8_t(needs[s] | (1u << n));
  std::vector<uint32_t> border;
  for (size_t i = 0; i < level.keys.size(); ++i) {
    const glm::ivec3 c(shared::mortonDecode(level.keys[i]));
    for (uint32_t s = 1; s < 8; ++s) {
      if ((level.masks[i] & needs[s]) == 0) continue;
      const glm::ivec3 d = c - glm::ivec3(int(s & 1u), int((s >> 1) & 1u), int((s >> 2) & 1u));
      if (d.x < 0 || d.y < 0 || d.z < 0) continue;
      border.push_back(shared::mortonEncode(glm::uvec3(d)));
    }
  }
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());
  LevelTiles merged;
  size_t a = 0, b = 0;
  while (a < level.keys.size() || b < border.size()) {
    if (b == border.size() || (a < level.keys.size() && level.keys[a] <= border[b])) {
      if (b < border.size() && border[b] == level.keys[a]) ++b;
      merged.keys.push_back(level.keys[a]);
      merged.masks.push_back(level.masks[a]);
      merged.border.push_back(0);
      ++a;
    } else {
      merged.keys.push_back(border[b++]);
      merged.masks.push_back(0);
      merged.border.push_back(1);
    }
  }
  level = std::move(merged);
}

}  // namespace

TileIndex::TileIndex(const std::vector<uint32_t>& sortedKeys, uint64_t keySpace)
    : bits_(size_t((keySpace + 63) / 64)), before_(bits_.size()) {
  for (const uint32_t k : sortedKeys) bits_[k >> 6] |= uint64_t(1) << (k & 63u);
  uint32_t count = 0;
  for (size_t w = 0; w < bits_.size(); ++w) {
    before_[w] = count;
    count += uint32_t(std::popcount(bits_[w]));
  }
}

uint32_t Octree::findTile(int level, uint32_t key) const {
  const uint32_t rank = levelIndex[size_t(level)].rank(key);
  if (rank == kSvoNull) return kSvoNull;
  return level == depth ? rank : levelStart[size_t(level)] + rank;
}

Octree buildOctree(std::span<const shared::SvoSample> samples, int depth,
                   const std::string& source) {
  std::vector<LevelTiles> levels(size_t(depth) + 1);
  levels[size_t(depth)] = markLeafTiles(samples, depth);
  for (int l = depth - 1; l >= 1; --l) levels[size_t(l)] = parentTiles(levels[size_t(l) + 1]);
  if (levels[1].keys.empty()) {  // no sample: the root tile alone, empty
    levels[1].keys = {0};
    levels[1].masks = {0};
    levels[1].border = {0};
  }
  for (int l = 2; l <= depth; ++l) addBorderTiles(levels[size_t(l)]);
  size_t tiles = 0;
  for (int l = 1; l <= depth; ++l) tiles += levels[size_t(l)].keys.size();
  // Node words, tile records and leaf sums per tile, as counted.
  requireMemory(tiles * 4 * (8 * kNodeWords + kTileWords + 8 * shared::kSumWords),
                "the octree's " + std::to_string(tiles) + " tiles", source, "grid.resolution");

  Octree o;
  o.depth = depth;
  o.levelStart.assign(size_t(depth) + 1, 0);
  o.levelIndex.resize(size_t(depth) + 1);
  for (int l = 1; l < depth; ++l)
    o.levelStart[size_t(l) + 1] = o.levelStart[size_t(l)] + uint32_t(levels[size_t(l)].keys.size());
  for (int l = 1; l <= depth; ++l)  // tile keys of level l have l - 1 bits per axis
    o.levelIndex[size_t(l)] = TileIndex(levels[size_t(l)].keys, uint64_t(1) << (3 * (l - 1)));

  // Tile records: level, key, parent node, flags.
  const auto writeTiles = [&](int l, Words& words) {
    const LevelTiles& level = levels[size_t(l)];
    words.resize(level.keys.size() * kTileWords);
    for (size_t i = 0; i < level.keys.size(); ++i) {
      uint32_t* w = &words[i * kTileWords];
      w[shared::kTileLevel] = uint32_t(l);
      w[shared::kTileKey] = level.keys[i];
      w[shared::kTileParent] = kSvoNull;
      if (l > 1) {
        const uint32_t parentTile = o.findTile(l - 1, level.keys[i] >> 3);
        w[shared::kTileParent] = parentTile * 8u + (level.keys[i] & 7u);
      }
      w[shared::kTileFlags] = level.border[i] ? shared::kTileBorder : 0u;
    }
  };
  Words nodeTileWords;
  for (int l = 1; l < depth; ++l) {
    Words words;
    writeTiles(l, words);
    nodeTileWords.insert(nodeTileWords.end(), words.begin(), words.end());
  }
  o.tiles = std::move(nodeTileWords);
  writeTiles(depth, o.leafTiles);

  // Nodes: child tile, neighbours, flags; one task per node tile.
  o.nodes.resize(o.tileCount() * 8 * kNodeWords);
  parallelFor(size_t(0), o.tileCount(), [&](size_t t) {
    const int l = int(o.tiles[t * kTileWords + shared::kTileLevel]);
    const uint32_t key = o.tiles[t * kTileWords + shared::kTileKey];
    const size_t rank = t - o.levelStart[size_t(l)];
    const uint8_t mask = levels[size_t(l)].masks[rank];
    const int side = 1 << l;
    for (uint32_t n = 0; n < 8; ++n) {
      uint32_t* w = &o.nodes[(t * 8 + n) * kNodeWords];
      const uint32_t nodeKey = (key << 3) | n;
      const uint32_t child = o.findTile(l + 1, nodeKey);
      uint32_t flags = (mask >> n) & 1u ? shared::kNodeReal : 0u;
      if (child != kSvoNull) {
        const LevelTiles& below = levels[size_t(l) + 1];
        const size_t childRank = l + 1 == depth ? child : child - o.levelStart[size_t(l) + 1];
        flags |= uint32_t(below.masks[childRank]) << shared::kNodeChildShift;
      }
      w[shared::kNodeChild] = child;
      w[shared::kNodeFlags] = flags;
      const glm::ivec3 x(shared::mortonDecode(nodeKey));
      for (int f = 0; f < 6; ++f) {
        glm::ivec3 y = x;
        y[f / 2] += f % 2 == 0 ? 1 : -1;
        uint32_t neighbour = kSvoNull;
        if (y[f / 2] >= 0 && y[f / 2] < side) {
          const uint32_t tile = o.findTile(l, shared::mortonEncode(glm::uvec3(y >> 1)));
          if (tile != kSvoNull) neighbour = tile * 8u + shared::localId(glm::uvec3(y));
        }
        w[shared::kNodeNeighbour + f] = neighbour;
      }
    }
  });
  return o;
}

Octree octreeFromWords(voxgi::svo::OctreeWords words, int depth) {
  Octree o;
  o.depth = depth;
  o.nodes = std::move(words.nodes);
  o.tiles = std::move(words.tiles);
  o.leafTiles = std::move(words.leafTiles);
  std::vector<std::vector<uint32_t>> keys(size_t(depth) + 1);
  for (size_t t = 0; t < o.tileCount(); ++t)
    keys[o.tiles[t * kTileWords + shared::kTileLevel]].push_back(
        o.tiles[t * kTileWords + shared::kTileKey]);
  for (size_t t = 0; t < o.leafTileCount(); ++t)
    keys[size_t(depth)].push_back(o.leafTiles[t * kTileWords + shared::kTileKey]);
  o.levelStart.assign(size_t(depth) + 1, 0);
  o.levelIndex.resize(size_t(depth) + 1);
  for (int l = 1; l < depth; ++l)
    o.levelStart[size_t(l) + 1] = o.levelStart[size_t(l)] + uint32_t(keys[size_t(l)].size());
  for (int l = 1; l <= depth; ++l)
    o.levelIndex[size_t(l)] = TileIndex(keys[size_t(l)], uint64_t(1) << (3 * (l - 1)));
  return o;
}

Words accumulateLeaves(const Octree& octree, std::span<const shared::SvoSample> samples,
                       float scale, const std::string& source) {
  using namespace shared;
  const int n = 1 << octree.depth;
  const size_t tiles = octree.leafTileCount();
  const TileIndex& index = octree.levelIndex[size_t(octree.depth)];
  // Each sample's home: the leaf tile of its first touched leaf on each axis (its touched leaves
  // lie in that tile or the next one along each axis). Samples go to their home's bucket, and each
  // tile then sums the samples of its own and its seven lower neighbours' buckets: every leaf is
  // written by one task, without atomics.
  const auto firstLeaf = [&](const SplatAxis& a) {
    if (a.w0 > 0.0f && a.lo >= 0 && a.lo < n) return a.lo;
    if (a.w1 > 0.0f && a.lo + 1 >= 0 && a.lo + 1 < n) return a.lo + 1;
    return -1;
  };
  std::vector<uint32_t> home(samples.size(), kSvoNull);
  // Bit a of reach: the sample's leaves reach into the next tile along axis a.
  std::vector<uint8_t> reach(samples.size(), 0);
  std::vector<std::atomic<uint32_t>> counts(tiles + 1);
  parallelFor(tbb::blocked_range<size_t>(0, samples.size(), 16384),
              [&](const tbb::blocked_range<size_t>& range) {
                for (size_t i = range.begin(); i != range.end(); ++i) {
                  const SvoSample& s = samples[i];
                  if (!splatInDomain(glm::vec3(s.position), float(n))) continue;
                  glm::ivec3 first;
                  uint8_t bits = 0;
                  for (int a = 0; a < 3; ++a) {
                    const SplatAxis axis = splatAxis(s.position[a], s.position.w);
                    first[a] = firstLeaf(axis);
                    const int last = axis.w1 > 0.0f && axis.lo + 1 < n ? axis.lo + 1 : axis.lo;
                    if (first[a] >= 0 && (last >> 1) > (first[a] >> 1))
                      bits = uint8_t(bits | (1 << a));
                  }
                  if (first.x < 0 || first.y < 0 || first.z < 0) continue;
                  home[i] = index.rank(mortonEncode(glm::uvec3(first >> 1)));
                  reach[i] = bits;
                  counts[home[i]].fetch_add(1, std::memory_order_relaxed);
                }
              });
  std::vector<uint32_t> start(tiles + 1, 0);
  for (size_t t = 0; t < tiles; ++t) start[t + 1] = start[t] + counts[t].load();
  // The samples in bucket order, scattered there from their input order (a tile then reads its
  // buckets from consecutive memory; a cloud's points come in any order). The order within a
  // bucket follows the threads, which the integer sums cannot see.
  for (size_t t = 0; t < tiles; ++t) counts[t].store(start[t]);
  std::vector<SvoSample, ZeroedAllocator<SvoSample>> sorted(start[tiles]);
  std::vector<uint8_t, ZeroedAllocator<uint8_t>> sortedReach(start[tiles]);
  parallelFor(tbb::blocked_range<size_t>(0, samples.size(), 16384),
              [&](const tbb::blocked_range<size_t>& range) {
                for (size_t i = range.begin(); i != range.end(); ++i) {
                  if (home[i] == kSvoNull) continue;
                  const uint32_t k = counts[home[i]].fetch_add(1, std::memory_order_relaxed);
                  sorted[k] = samples[i];
                  sortedReach[k] = reach[i];
                }
              });
  Words sums(tiles * 8 * kSumWords);
  std::atomic<bool> overflow{false};
  parallelFor(size_t(0), tiles, [&](size_t t) {
    const glm::ivec3 tile(mortonDecode(octree.leafTiles[t * kTileWords + kTileKey]));
    int32_t local[8][kSumWords] = {};
    for (int o = 0; o < 8; ++o) {
      const glm::ivec3 h = tile - glm::ivec3(o & 1, (o >> 1) & 1, o >> 2);
      if (h.x < 0 || h.y < 0 || h.z < 0) continue;
      const uint32_t bucket = index.rank(mortonEncode(glm::uvec3(h)));
      if (bucket == kSvoNull) continue;
      for (uint32_t k = start[bucket]; k < start[bucket + 1]; ++k) {
        if ((sortedReach[k] & o) != o) continue;  // its leaves stop short of this tile
        const SvoSample& s = sorted[k];
        forEachLeaf(s, n, [&](glm::ivec3 leaf, float w) {
          if ((leaf >> 1) != tile) return;  // another tile's: it sums it from this bucket
          int32_t* v = local[localId(glm::uvec3(leaf))];
          const int opacity = fixedRound(w, 1.0f, scale);
          if (v[kSumOpacity] > std::numeric_limits<int32_t>::max() - opacity) {
            overflow.store(true, std::memory_order_relaxed);
            return;
          }
          v[kSumOpacity] += opacity;
          for (int ch = 0; ch < 3; ++ch) {
            v[kSumAlbedo + ch] += fixedRound(w, s.albedo[ch], scale);
            v[kSumNormal + ch] += fixedRound(w, s.normal[ch], scale);
            v[kSumEmission + ch] += fixedRound(w, s.emission[ch], scale);
          }
        });
      }
    }
    for (int leaf = 0; leaf < 8; ++leaf)
      for (int c = 0; c < kSumWords; ++c)
        sums[(t * 8 + size_t(leaf)) * kSumWords + size_t(c)] = uint32_t(local[leaf][c]);
  });
  if (overflow.load())
    throw InputError(
        source, "grid.resolution",
        "a leaf's opacity passes 2^31 fixed-point units; raise grid.resolution or thin "
        "the point cloud");
  return sums;
}

Words completeBricks(const Octree& octree, int level, const Words& interior, int components) {
  using namespace shared;
  const bool leaves = level == octree.depth;
  const Words& tiles = leaves ? octree.leafTiles : octree.tiles;
  const size_t first = leaves ? 0 : octree.levelStart[size_t(level)];
  const size_t count =
      leaves ? octree.leafTileCount()
             : octree.levelStart[size_t(level) + 1] - octree.levelStart[size_t(level)];
  const auto c = size_t(components);
  Words bricks(count * kBrickTexels * c);
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

}  // namespace voxgi::cpu::svo
