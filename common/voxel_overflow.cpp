#include "common/voxel_overflow.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "common/error.h"
#include "common/fnv1a.h"
#include "common/voxel_walk.h"

namespace voxgi {
namespace {

// A triangle's geometry (what its weights depend on), compared bit for bit.
struct Key {
  float v[9];
  bool operator==(const Key& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
};

struct KeyHash {
  size_t operator()(const Key& k) const { return size_t(fnv1a(k.v, sizeof k.v)); }
};

Key keyOf(const shared::VoxelTriangle& t) {
  return {{t.v0.x, t.v0.y, t.v0.z, t.v1.x, t.v1.y, t.v1.z, t.v2.x, t.v2.y, t.v2.z}};
}

}  // namespace

void refuseRepeatedTriangles(const VoxelTriangles& triangles, int n, bool antialiased,
                             const std::string& file) {
  // A triangle with fewer copies than `fewest` is not walked. One copy puts about its area in a
  // voxel into it, at most sqrt(2) faces (the largest plane section of a cube); an antialiased
  // sample spreads over the eight voxels of its tent cell, at most 4 sqrt(2) faces from a 2x2x2
  // block. The bounds below leave room for rounding and sub-triangles that straddle a block. A
  // triangle skipped wrongly would still be caught while accumulating, only later: the bound
  // decides how much is walked here (nothing, in a scene without thousands of copies), never the
  // result.
  const double perCopy = (antialiased ? 8.0 : 2.0) * shared::kWeightScale + 1.0;
  const uint64_t fewest = uint64_t(double(shared::kMaxWeightSum) / perCopy);
  // First a count per hash bucket, which no triangle with `fewest` copies escapes: most scenes
  // stop here, after one pass with no allocation per triangle. Only triangles in a heavy bucket
  // are counted exactly.
  const KeyHash hash;
  std::vector<uint32_t> buckets(size_t(1) << 16, 0);
  const auto bucket = [&](const shared::VoxelTriangle& t) {
    return hash(keyOf(t)) & (buckets.size() - 1);
  };
  for (const shared::VoxelTriangle& t : triangles.triangles) ++buckets[bucket(t)];
  if (*std::max_element(buckets.begin(), buckets.end()) <= fewest) return;
  std::unordered_map<Key, uint64_t, KeyHash> copies;
  const TexturePool none;
  const TextureAccess noTextures{none};
  for (const shared::VoxelTriangle& t : triangles.triangles)
    if (buckets[bucket(t)] > fewest) ++copies[keyOf(t)];
  for (const shared::VoxelTriangle& t : triangles.triangles) {
    const auto it = copies.find(keyOf(t));
    if (it == copies.end() || it->second <= fewest) continue;
    const uint64_t count = it->second;
    copies.erase(it);                             // each repeated triangle is walked once
    std::unordered_map<size_t, uint64_t> weight;  // one copy's weight per voxel
    const auto sink = [&](const glm::ivec3& v, const shared::VoxelContribution& c) {
      weight[(size_t(v.z) * size_t(n) + size_t(v.y)) * size_t(n) + size_t(v.x)] += c.weight;
    };
    // Only the weights count here: the copy is walked without its textures.
    shared::VoxelTriangle plain = t;
    plain.albedoTexture = plain.emissionTexture = shared::kNoTexture;
    if (antialiased)
      antialiasedWalk(plain, n, noTextures, sink);
    else
      conservativeWalk(plain, n, noTextures, sink);
    uint64_t heaviest = 0;
    for (const auto& [voxel, w] : weight) heaviest = std::max(heaviest, w);
    if (count * heaviest > shared::kMaxWeightSum)
      throw InputError(file, "meshes",
                       "a triangle is repeated " + std::to_string(count) +
                           " times, and its copies put more than 32768 voxel faces of surface "
                           "into one voxel (fixed-point overflow); remove the duplicates or "
                           "lower grid.resolution");
  }
}

}  // namespace voxgi
