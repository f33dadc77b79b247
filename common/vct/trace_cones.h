// trace_cones' host preparation: the lights, cone set, per-object records and the parameter block
// the cone kernels read (shaders/shared/vct/cone_kernel.h), prepared once for both backends (and
// for bounce and the octree's stages, which march the same cones).
#pragma once

#include <vector>

#include "common/stage.h"
#include "shaders/shared/lighting.h"
#include "shaders/shared/vct/cone_kernel.h"

namespace voxgi {

// The cone kernels' parameters for `lightCount` lights and `coneCount` diffuse cones, seen from
// `cameraPosition` (voxel-local).
shared::ConeTraceParams coneTraceParams(const StageContext& ctx, int lightCount, int coneCount,
                                        glm::vec3 cameraPosition);

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
}  // namespace voxgi
