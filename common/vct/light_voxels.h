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

// In a sequence (ctx.previous holding the frame before's radiance), when meshes moved and the
// lights and parameters are the frame before's: the box voxelize's buffers changed in, for
// lightVoxelMayChange; partial = 0 (light every voxel) otherwise. `setup` is this frame's.
shared::LightVoxelsUpdate lightVoxelsUpdate(const StageContext& ctx, const LightVoxelsSetup& setup,
                                            bool emissionVolume);

}  // namespace voxgi
