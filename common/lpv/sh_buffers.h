// Which SH buffers a light propagation volume run uses: 2 bands write the *_sh4 buffers, 3 bands
// the *_sh9 ones (common/lpv/stages.inc), so each buffer has one component count.
#pragma once

#include "common/settings.h"
#include "common/stage_list.h"

namespace voxgi::lpv {

struct ShBuffers {
  BufferId intensitySum;  // inject
  BufferId steps;         // propagate, with propagate.history=on
  BufferId accumulated;   // propagate
  Effect coefficients;    // sh4 or sh9
  Effect history;         // sh4_steps or sh9_steps
};

inline ShBuffers shBuffers(const LpvSettings& s) {
  using enum BufferId;
  if (s.bands == 2)
    return {lpv_inject_intensity_sum_sh4, lpv_propagate_steps_sh4, lpv_propagate_accumulated_sh4,
            Effect::sh4, Effect::sh4_steps};
  return {lpv_inject_intensity_sum_sh9, lpv_propagate_steps_sh9, lpv_propagate_accumulated_sh9,
          Effect::sh9, Effect::sh9_steps};
}

// Propagation steps: propagate.steps, or half the grid's resolution when it is 0 (light moves
// about a cell per step, so N/2 steps carry it from the middle of the grid to its border).
inline int propagationSteps(const LpvSettings& s, int resolution) {
  return s.steps > 0 ? s.steps : (resolution / 2 > 0 ? resolution / 2 : 1);
}

}  // namespace voxgi::lpv
