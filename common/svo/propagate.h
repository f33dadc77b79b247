// propagate's host preparation for both backends: what propagate.carry carries from one frame of
// a sequence to the next (docs/svo.md, "Progressive bounces in a sequence"). The light a frame's
// gathers leave is kept by leaf, under the leaf's Morton key, in the runner's FrameHistory; the
// next frame's first gather starts from each leaf's direct light plus its albedo times that
// light, so that bounce n of a light that changed at frame t0 shows from frame t0 + n - 1 (area
// lights: emission is bounce 0) or t0 + n - 2 (analytic lights: their reflection is bounce 1
// [Salm 2015, §4.4.3]).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "common/buffer.h"
#include "common/stage.h"
#include "common/svo/light_types.h"

namespace voxgi::svo {

// The gathered light of a frame by leaf: the leaf tiles' Morton keys in build's order (ascending)
// and per leaf slot (8 a tile) the gathered E / pi itself, not premultiplied.
struct CarriedLight {
  std::vector<uint32_t> tileKeys;
  std::vector<glm::vec3> gathered;
};

// Whether propagate carries light across frames under `settings`: propagate.carry=on, and its
// frames gather from the light before them (propagate.frames > 0, clear_each_frame off).
bool carriesLight(const Settings& settings);

// The frame before's carried light where the stage carries and the runner kept some; none in the
// first frame of a sequence and outside one.
std::optional<CarriedLight> carriedIn(const StageContext& ctx);

// The first gather's source under `before`: per real leaf, its direct light plus its albedo times
// the light carried by the leaf of the same key (gather.h's addReflected, as a gather
// writes it); a leaf the frame before did not have starts from its direct light. `leafTiles` is
// build's leaf_tiles buffer.
LeafRadiance carriedSource(const CarriedLight& before, const Words& leafTiles, const Leaves& leaves,
                           const LeafRadiance& direct);

// Keeps this frame's gathered light (straight, per leaf slot) in ctx.history where the stage
// carries, and marks the stage settled when it is the light it started from, word for word.
void carryOut(const StageContext& ctx, const Words& leafTiles,
              std::vector<glm::vec3> gatheredStraight);

}  // namespace voxgi::svo
