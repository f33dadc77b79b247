#include "common/vct/light_voxels.h"

#include <cstring>

#include "common/lights.h"
#include "common/voxelize_update.h"

namespace voxgi {

LightVoxelsSetup prepareLightVoxels(const StageContext& ctx, bool emissionVolume) {
  const EmitterLighting emitters = emittersFor(ctx.scene, ctx.settings.vct.emitters);
  LightVoxelsSetup s{sceneLights(ctx.scene, emitters), {}};
  s.params = lightVoxelsParams(ctx, int(s.lights.size()),
                               emissionVolume && emitters == EmitterLighting::voxels);
  return s;
}

shared::LightVoxelsUpdate lightVoxelsUpdate(const StageContext& ctx, const LightVoxelsSetup& setup,
                                            bool emissionVolume) {
  shared::LightVoxelsUpdate update{};
  const PreviousFrame* p = ctx.previous;
  if (p == nullptr || !p->stash.contains(BufferId::vct_light_voxels_radiance)) return update;
  const std::optional<VoxelBox> box = changedVoxelBox(ctx);
  if (!box) return update;
  // The lights as the kernel reads them, emissive triangles included, compared word for word.
  const StageContext before(ctx.technique, *p->scene, ctx.settings, *p->triangles);
  const LightVoxelsSetup then = prepareLightVoxels(before, emissionVolume);
  if (then.lights.size() != setup.lights.size() ||
      std::memcmp(&then.params, &setup.params, sizeof setup.params) != 0 ||
      (!setup.lights.empty() && std::memcmp(then.lights.data(), setup.lights.data(),
                                            setup.lights.size() * sizeof(shared::LightData)) != 0))
    return update;
  update.changedLow = box->low;
  update.changedHigh = box->high;
  update.partial = 1;
  return update;
}

}  // namespace voxgi
