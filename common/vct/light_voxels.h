// light_voxels' host preparation: the lights and the parameter block its kernel reads
// (shaders/shared/cone/voxel_light.h, common/cone/voxel_light.h), prepared once for both
// backends, and what a sequence's frame may skip.
#pragma once

#include <vector>

#include "common/cone/voxel_light.h"

namespace voxgi {

// What vct's light_voxels reads besides the volumes: the scene's analytic lights, then under
// emitters.mode=area_lights its emissive triangles, whose voxels then carry no emission.
struct LightVoxelsSetup {
  std::vector<shared::LightData> lights;
  shared::LightVoxelsParams params;
};
// `emissionVolume`: voxelize produced the emission volume.
LightVoxelsSetup prepareLightVoxels(const StageContext& ctx, bool emissionVolume);

// In a sequence (ctx.previous holding the frame before's radiance), when meshes moved and the
// lights and parameters are the frame before's: the box voxelize's buffers changed in, for
// lightVoxelMayChange; partial = 0 (light every voxel) otherwise. `setup` is this frame's.
shared::LightVoxelsUpdate lightVoxelsUpdate(const StageContext& ctx, const LightVoxelsSetup& setup,
                                            bool emissionVolume);

}  // namespace voxgi
