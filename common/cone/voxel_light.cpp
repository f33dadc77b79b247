#include "common/cone/voxel_light.h"

namespace voxgi {

shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount,
                                            bool emission) {
  const VctSettings& s = ctx.settings.vct;
  shared::LightVoxelsParams p{};
  p.resolution = ctx.scene.grid.resolution;
  p.lightCount = lightCount;
  p.normalWeighted = s.attenuation == LightAttenuation::normal_weighted ? 1 : 0;
  p.voxelShadow = static_cast<int>(s.voxelShadow);
  p.voxelSize = static_cast<float>(ctx.scene.grid.voxelSize());
  p.shadowKappa = s.voxelShadowKappa;
  p.shadowOffset = s.voxelShadowOffset;
  p.emissive = emission ? 1 : 0;
  return p;
}

}  // namespace voxgi
