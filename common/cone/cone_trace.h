// The cone library's host preparation: the lights, cone set, per-object records and the parameter
// block the cone kernels read (shaders/shared/cone/march.h), prepared once for both backends, for
// the stages that march cones from pixels (vct's trace_cones, svo's shade) and those that gather
// with them at voxels (vct's bounce, svo's propagate).
#pragma once

#include <vector>

#include "common/stage.h"
#include "shaders/shared/cone/march.h"
#include "shaders/shared/lighting.h"

namespace voxgi {

// The cone kernels' parameters for `lightCount` lights and `coneCount` diffuse cones, seen from
// `cameraPosition` (voxel-local).
shared::ConeTraceParams coneTraceParams(const StageContext& ctx, int lightCount, int coneCount,
                                        glm::vec3 cameraPosition);

// What the cones of a pixel read besides the gbuffer and the volumes.
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

// The same for a gather at voxels (shaders/shared/cone/gather.h): the diffuse cone set only (no
// lights, objects or ambient occlusion).
ConeTraceSetup prepareGather(const StageContext& ctx);

}  // namespace voxgi
