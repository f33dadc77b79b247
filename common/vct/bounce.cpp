#include "common/vct/bounce.h"

#include "common/vct/cone_sets.h"

namespace voxgi {

ConeTraceSetup prepareBounce(const StageContext& ctx) {
  ConeTraceSetup s{{}, coneData(diffuseCones(ctx.settings.vct.cones)), {}, {}};
  s.params = coneTraceParams(ctx, 0, int(s.cones.size()), glm::vec3(0.0f));
  s.params.ambientOcclusion = 0;  // a bounce gathers radiance; occlusion is a pixel's
  return s;
}

}  // namespace voxgi
