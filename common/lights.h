// The scene's analytic lights as the shaders see them (shaders/shared/lighting.h): voxel-local
// positions, spot cut-off cosines and falloff packed once on the host for both backends.
#pragma once

#include <vector>

#include "common/scene.h"
#include "shaders/shared/lighting.h"

namespace voxgi {

std::vector<shared::LightData> voxelLights(const Scene& scene);

}  // namespace voxgi
