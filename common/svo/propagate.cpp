#include "common/svo/propagate.h"

#include <bit>

#include "common/svo/tree_depth.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/svo/svo_layout.h"
#include "shaders/shared/cone/gather.h"

namespace voxgi::svo {
namespace {

std::vector<uint32_t> tileKeys(const Words& leafTiles) {
  std::vector<uint32_t> keys(leafTiles.size() / shared::kTileWords);
  for (size_t t = 0; t < keys.size(); ++t)
    keys[t] = leafTiles[t * shared::kTileWords + shared::kTileKey];
  return keys;
}

// FrameHistory words: the tree's depth, the tile count, the keys, then three float words a leaf
// slot.
std::vector<uint32_t> pack(int depth, const CarriedLight& light) {
  std::vector<uint32_t> words{uint32_t(depth), uint32_t(light.tileKeys.size())};
  words.insert(words.end(), light.tileKeys.begin(), light.tileKeys.end());
  for (const glm::vec3& g : light.gathered)
    for (int c = 0; c < 3; ++c) words.push_back(std::bit_cast<uint32_t>(g[c]));
  return words;
}

CarriedLight unpack(const std::vector<uint32_t>& words) {
  CarriedLight light;
  const size_t tiles = words.at(1);
  light.tileKeys.assign(words.begin() + 2, words.begin() + 2 + ptrdiff_t(tiles));
  light.gathered.resize(tiles * 8);
  const uint32_t* g = words.data() + 2 + tiles;
  for (size_t s = 0; s < light.gathered.size(); ++s)
    for (int c = 0; c < 3; ++c) light.gathered[s][c] = std::bit_cast<float>(g[3 * s + size_t(c)]);
  return light;
}

}  // namespace

bool carriesLight(const Settings& settings) {
  const SvoSettings& s = settings.svo;
  return s.carry == SvoToggle::on && s.frames > 0 && s.clearEachFrame == SvoToggle::off;
}

std::optional<CarriedLight> carriedIn(const StageContext& ctx) {
  if (ctx.history == nullptr || !ctx.plan.carries(StageId::svo_propagate)) return std::nullopt;
  const auto it = ctx.history->carried.find(StageId::svo_propagate);
  // Keys of another depth name other leaves (a sequence keeps its grid, but the runner does not
  // require it).
  if (it == ctx.history->carried.end() || it->second.at(0) != uint32_t(treeDepth(ctx.scene)))
    return std::nullopt;
  return unpack(it->second);
}

LeafRadiance carriedSource(const CarriedLight& before, const Words& leafTiles, const Leaves& leaves,
                           const LeafRadiance& direct) {
  LeafRadiance source = direct;
  const std::vector<uint32_t> keys = tileKeys(leafTiles);
  // Both key lists ascend: one merge walk.
  size_t b = 0;
  for (size_t t = 0; t < keys.size(); ++t) {
    while (b < before.tileKeys.size() && before.tileKeys[b] < keys[t]) ++b;
    if (b == before.tileKeys.size() || before.tileKeys[b] != keys[t]) continue;
    for (size_t local = 0; local < 8; ++local) {
      const size_t slot = t * 8 + local;
      const glm::vec4 a = leaves.albedo[slot];
      // A tile's empty leaves have no opacity: they stay as direct left them (zero).
      if (!(a.a > 0.0f)) continue;
      // As the CPU gather's albedoAt: the albedo per unit of opacity.
      source[slot] = shared::roundToHalf4(
          shared::addReflected(direct[slot], glm::vec3(a) / a.a, before.gathered[b * 8 + local]));
    }
  }
  return source;
}

void carryOut(const StageContext& ctx, const Words& leafTiles,
              std::vector<glm::vec3> gatheredStraight) {
  if (ctx.history == nullptr || !ctx.plan.carries(StageId::svo_propagate)) return;
  std::vector<uint32_t> words =
      pack(treeDepth(ctx.scene), {tileKeys(leafTiles), std::move(gatheredStraight)});
  std::vector<uint32_t>& kept = ctx.history->carried[StageId::svo_propagate];
  if (words == kept)
    ctx.history->settled.insert(StageId::svo_propagate);
  else
    ctx.history->settled.erase(StageId::svo_propagate);
  kept = std::move(words);
}

}  // namespace voxgi::svo
