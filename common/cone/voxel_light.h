// The voxel light kernel's parameter block (shaders/shared/cone/voxel_light.h) from the settings,
// prepared once for both backends, for every stage that lights voxels with it (vct's
// light_voxels, svo's propagate).
#pragma once

#include "common/stage.h"
#include "shaders/shared/cone/voxel_light.h"

namespace voxgi {

// `emission`: the voxels' emission is added to their radiance.
shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount, bool emission);

}  // namespace voxgi
