// Settings and scene packed into the parameter blocks the shared kernels read (shaders/shared/),
// once, so both backends get the same values.
#pragma once

#include "common/stage.h"
#include "shaders/shared/vct/cone_kernel.h"
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

// What trace_cones reads besides the gbuffer and the volumes, prepared once for both backends.
struct ConeTraceSetup {
  std::vector<shared::LightData> lights;
  std::vector<shared::ConeData> cones;
  // One record per object id (index 0: the background): the specular cone's tan(aperture / 2),
  // from the shininess so the cone holds half the Phong lobe's energy; for glossy materials only,
  // or for every object under plan.mode=full.
  std::vector<shared::ObjectData> objects;
  shared::ConeTraceParams params;
};
ConeTraceSetup prepareConeTrace(const StageContext& ctx);
// The same for the bounce stage: the diffuse cone set only (no lights, objects or ambient
// occlusion).
ConeTraceSetup prepareBounce(const StageContext& ctx);

}  // namespace voxgi
