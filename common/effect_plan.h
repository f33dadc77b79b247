// The effect planner (DESIGN.md): which stages, buffers and cones a scene needs, decided once from
// the scene and the settings so that a scene pays only for the effects it uses. Stages read the
// decisions from StageContext::plan; `voxgi plan` prints them with the reason for each.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/scene.h"
#include "common/settings.h"

namespace voxgi {

// One line of the plan: a stage or an effect, whether it runs, and why.
struct PlanItem {
  std::string name;
  bool in = true;
  std::string why;
};

struct EffectPlan {
  bool full = false;              // plan.mode=full: every optional effect below is computed
  bool emission = false;          // emission volume, emitted radiance per voxel and per pixel
  bool specular = false;          // specular cone and direct specular lobe per pixel
  bool ambientOcclusion = false;  // the ambient_occlusion buffer
  int shadowLights = 0;           // lights that trace a shadow cone per pixel
  int bounces = 0;                // runs of the bounce stage
  MipMode mip = MipMode::anisotropic;
  std::vector<PlanItem> items;  // stages in graph order, each followed by its effects

  // Whether the stage runs at all (bounce only with bounce.count > 0).
  bool runs(std::string_view stage) const;
};

EffectPlan planEffects(const Scene& scene, const Settings& settings);

// Whether any triangle of `mesh` can be in the camera's view: false only when its bounding box
// lies wholly outside one plane of the view frustum (conservative).
bool meshInView(const Scene& scene, const Mesh& mesh);

}  // namespace voxgi
