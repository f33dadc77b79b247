// light_voxels' host preparation: the lights and the parameter block its kernel reads
// (shaders/shared/vct/light_voxels_kernel.h), prepared once for both backends (and for the
// octree's propagate, which lights its leaves with the same kernel).
#pragma once

#include <vector>

#include "common/stage.h"
#include "shaders/shared/vct/light_voxels_kernel.h"

namespace voxgi {

// `emission`: the voxels' emission is added to their radiance.
shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount, bool emission);

// What vct's light_voxels reads besides the volumes: the scene's analytic lights, then under
// emitters.mode=area_lights its emissive triangles, whose voxels then carry no emission.
struct LightVoxelsSetup {
  std::vector<shared::LightData> lights;
  shared::LightVoxelsParams params;
};
// `emissionVolume`: voxelize produced the emission volume.
LightVoxelsSetup prepareLightVoxels(const StageContext& ctx, bool emissionVolume);

}  // namespace voxgi
