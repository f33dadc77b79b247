// The diffuse cone sets of `cones.set` (docs/stages/vct/trace_cones.md): cone directions in the
// tangent frame (z along the normal), apertures and weights. Every set's weights sum to 1, so a
// uniform environment of radiance L gives indirect diffuse E / pi = L exactly (the white furnace);
// the sets differ in how well they follow the cosine lobe.
#pragma once

#include <vector>

#include "common/settings.h"
#include "shaders/shared/cone/march.h"

namespace voxgi {

struct Cone {
  glm::vec3 direction;  // unit, tangent frame
  float aperture;       // full angle, radians
  float weight;
};

std::vector<Cone> diffuseCones(ConeSet set);

// Packed for the shared kernel: tan(aperture / 2) computed here, once, for both backends.
std::vector<shared::ConeData> coneData(const std::vector<Cone>& cones);

}  // namespace voxgi
