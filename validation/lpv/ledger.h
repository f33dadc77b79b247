// The energy ledger of a light propagation volume run (docs/lpv.md, "Where the light goes"): per
// propagation step, the flux the faces send, what the geometry volume removes, what leaves the
// grid and what arrives, and the flux shading reads from each step's volume over every surface of
// the scene, against the flux the emitters and RSM texels inject. Computed from the buffers of a
// CPU or GPU run with every step's volume kept (propagate.history=on), with the shared kernels'
// own arithmetic for each face, in double, so that its closure checks the propagate stage.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/stage.h"

namespace voxgi::validation {

// Flux per colour in the scene's units (radiance x area), so that a closed box's surfaces
// receive the emitted flux.
struct LedgerStep {
  int step = 0;             // 1: LPV_0 -> LPV_1
  glm::dvec3 sent{0.0};     // what every face entry re-emits before occlusion (its lobe's flux)
  glm::dvec3 removed{0.0};  // sent x the geometry volume's blocking, toward cells in the grid
  glm::dvec3 left{0.0};     // sent toward cells outside the grid: lost
  glm::dvec3 arrived{0.0};  // sent - removed - left: LPV_k's flux by the faces
  glm::dvec3 volume{0.0};   // LPV_k's flux as the stage wrote it (2 sqrt(pi) c_0 summed)
  glm::dvec3 read{0.0};     // irradiance shading reads from LPV_k alone, over every surface
};

struct LedgerSurface {
  std::string name;      // the mesh's name
  double area = 0.0;     // world units
  glm::dvec3 read{0.0};  // irradiance from the accumulated volume, integrated over the mesh
};

struct Ledger {
  glm::dvec3 emitted{0.0};       // the emitters' flux (pi x emission x area) + the RSM texels'
  glm::dvec3 injected{0.0};      // LPV_0's flux: what of it lands in the grid
  glm::dvec3 readInjected{0.0};  // what shading reads from LPV_0 (in the accumulated volume when
                                 // propagate.accumulate_injection=on)
  std::vector<LedgerStep> steps;
  glm::dvec3 read{0.0};  // from the accumulated volume over every surface: the sum of the steps'
  std::vector<LedgerSurface> surfaces;
  double samplesPerCell = 0.0;  // surface samples per cell face of area
};

// `buffers`: a run of the lpv technique (ctx) up to propagate, with propagate.history=on. Surfaces
// are integrated at the centroids of sub-triangles of at most `spacing` cells a side, with the
// shading kernel's irradiance at shade.offset.
Ledger lpvLedger(const StageContext& ctx, const BufferSet& buffers, double spacing = 0.5);

}  // namespace voxgi::validation
