// The reflective shadow maps' views, prepared once on the host for the rsm stage, inject and
// shade on both backends (docs/stages/lpv/rsm.md).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/scene.h"
#include "common/settings.h"
#include "shaders/shared/lighting.h"
#include "shaders/shared/lpv/lpv_types.h"

namespace voxgi::lpv {

struct RsmSetup {
  shared::RsmParams params{};
  // The lights the maps are of: the analytic lights, then, under emitters.mode=area_lights, every
  // emissive triangle (common/lights.h, sceneLights). shade's direct light loops over them.
  std::vector<shared::LightData> lights;
  std::vector<shared::RsmView> views;  // grouped by light, in the lights' order
};

// The views of each light: six cube faces for a point light, for a spot whose cone is wider than
// 120 degrees and for an emissive triangle (from its centroid), one frustum of the cone's half
// angle for a narrower spot, and an orthographic box around the grid's bounding sphere for a
// directional light, starting behind every vertex of the scene.
RsmSetup prepareRsm(const Scene& scene, const Settings& s);
// The view count alone (the plan's map count).
int rsmViewCount(const Scene& scene, const Settings& s);

// An OpenGL view-projection of the view with depth in [0, farPlane] cells (perspective: from
// 1e-2), y flipped so that framebuffer row 0 is texel row 0 and fragment centres are the CPU's
// texel rays.
glm::mat4 rsmViewProjection(const shared::RsmView& v, float farPlane);
// Beyond every vertex of the scene from any view's origin, in cells.
float rsmFarPlane(const Scene& scene, const RsmSetup& rsm);

// An upper bound of the flux per colour the RSM texels inside the grid can carry: the largest
// albedo times, per analytic light, its irradiance at the grid's farthest corner times the views'
// total cross-section there (exact for inverse-square falloff), and per emissive triangle the
// flux it emits, pi x emission x area. inject's fixed-point scale uses it, so the scale does
// not depend on what the maps saw.
glm::dvec3 rsmFluxBound(const Scene& scene, const RsmSetup& rsm);

}  // namespace voxgi::lpv
