// inject's input, prepared once on the host for both backends: the virtual point lights of
// the scene's emissive triangles, and the fixed-point scale of all VPLs' sums, the RSM texels'
// included (docs/stages/lpv/inject.md).
#pragma once

#include <vector>

#include "common/stage.h"
#include "shaders/shared/lpv/inject_kernel.h"
#include "shaders/shared/lpv/lpv_types.h"

namespace voxgi::lpv {

struct Injection {
  shared::InjectParams params{};
  std::vector<shared::Vpl> vpls;
};

// Each emissive triangle (one-sided, as the path tracer's) is split into m^2 congruent
// sub-triangles, m = ceil(longest edge / (inject.emitter_spacing cells)); a VPL at each centroid
// carries the sub-triangle's flux, pi x emission x area. Positions in voxel-local coordinates,
// computed in double. The scale per colour is the largest power of two with scale x total flux
// <= 2^30, the total being the emitters' flux plus the bound of common/lpv/rsm.h on the RSM
// texels': a lobe coefficient is at most a third of its VPL's flux, so no cell's sum can reach
// 2^31. Throws InputError naming the scene's inject.emitter_spacing when the VPLs would not fit
// in memory.
Injection prepareInjection(const StageContext& ctx);
// prepareInjection(ctx).params.scale without the VPLs.
glm::vec4 injectionScale(const StageContext& ctx);
// LPV_0, the volume propagate starts from: inject's fixed-point `sums` as floats (the same
// words for both backends, computed once on the host), a cell's 3C words together.
std::vector<float> injectedVolume(const StageContext& ctx, const Buffer& sums);
// The same values handed to at(row, x, word, value) (row = y + n z) in the sums' order, for a
// caller that lays the volume out its own way.
template <class At>
void decodeInjected(const StageContext& ctx, const Buffer& sums, At&& at) {
  const glm::vec4 scale = injectionScale(ctx);
  const int n = ctx.scene.grid.resolution, coefficients = ctx.settings.lpv.coefficients();
  size_t w = 0;
  for (int row = 0; row < n * n; ++row)
    for (int x = 0; x < n; ++x)
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < coefficients; ++i, ++w)
          at(row, x, c * coefficients + i,
             shared::injectedIntensity(static_cast<int32_t>(sums.words[w]), scale[c]));
}

}  // namespace voxgi::lpv
