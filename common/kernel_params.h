// Settings and scene packed into the parameter blocks the shared kernels read (shaders/shared/),
// once, so both backends get the same values.
#pragma once

#include "common/stage.h"
#include "shaders/shared/light_voxels_kernel.h"

namespace voxgi {

shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount, bool emissive);

}  // namespace voxgi
