// The scene's analytic lights as the shaders see them (shaders/shared/lighting.h): voxel-local
// positions, spot cut-off cosines and falloff packed once on the host for both backends.
#pragma once

#include <vector>

#include "common/scene.h"
#include "common/settings.h"
#include "shaders/shared/lighting.h"

namespace voxgi {

std::vector<shared::LightData> voxelLights(const Scene& scene);

// The most emissive triangles emitters.mode=area_lights takes: each costs a shadow cone per pixel.
constexpr size_t kMaxAreaLights = 64;

// The triangles of the scene's meshes with an emissive material: its area lights under
// emitters.mode=area_lights (a degenerate one counted too; areaLights leaves it out).
size_t emissiveTriangleCount(const Scene& scene);

// What emitters.mode `setting` means for `scene`: voxels or area_lights (auto: area lights up to
// kMaxAreaLights emissive triangles, each costing a shadow cone per pixel, else voxels).
EmitterLighting emittersFor(const Scene& scene, EmitterLighting setting);

// The scene's area lights under emitters.mode `setting` (emittersFor): its emissive triangles, or
// none.
size_t areaLightCount(const Scene& scene, EmitterLighting setting);

// Every emissive triangle of the scene's meshes as an area light (shared::kLightTriangle);
// degenerate ones are left out. Throws InputError naming the scene and emitters.mode past
// kMaxAreaLights.
std::vector<shared::LightData> areaLights(const Scene& scene);

// The lights a technique's stages loop over: the analytic lights (voxelLights), then the area
// lights when emitters.mode `setting` means them.
std::vector<shared::LightData> sceneLights(const Scene& scene, EmitterLighting setting);

}  // namespace voxgi
