// Which radiance volume and pyramid a cone tracing stage reads: the pyramid mip.mode asks for, and
// bounce's buffers when the plan runs bounce, else light_voxels' and mip's.
#pragma once

#include "common/stage.h"

namespace voxgi {

inline int pyramidFaces(MipMode mode) {
  return mode == MipMode::isotropic ? 1 : 6;
}

// The pyramid `stage` (mip or bounce) writes for `mode`.
inline BufferId pyramidBuffer(StageId stage, MipMode mode) {
  const bool iso = mode == MipMode::isotropic;
  return stage == StageId::vct_bounce
             ? (iso ? BufferId::vct_bounce_radiance_mips : BufferId::vct_bounce_radiance_mips6)
             : (iso ? BufferId::vct_mip_radiance_mips : BufferId::vct_mip_radiance_mips6);
}

struct RadianceBuffers {
  BufferId radiance;  // level 0
  BufferId pyramid;   // levels 1..log2 N
};

// The lit volumes before any bounce: light_voxels' radiance and mip's pyramid.
inline RadianceBuffers directRadiance(MipMode mode) {
  return {BufferId::vct_light_voxels_radiance, pyramidBuffer(StageId::vct_mip, mode)};
}

// What trace_cones reads: the last bounce when the plan runs bounce, else the direct light.
inline RadianceBuffers finalRadiance(const StageContext& ctx) {
  const MipMode mode = ctx.settings.vct.mip;
  if (!ctx.plan.runs(StageId::vct_bounce)) return directRadiance(mode);
  return {BufferId::vct_bounce_radiance, pyramidBuffer(StageId::vct_bounce, mode)};
}

}  // namespace voxgi
