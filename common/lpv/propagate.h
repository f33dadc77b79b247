// propagate's input, prepared once on the host for both backends: the face-entry table of one
// step (shared::PropagationEntry, from the solid angles of common/lpv/propagation_faces.h,
// computed in double and rounded once) and the step's parameters.
#pragma once

#include <cstdint>
#include <vector>

#include "common/stage.h"
#include "shaders/shared/lpv/lpv_types.h"

namespace voxgi::lpv {

struct Propagation {
  shared::PropagateParams params{};  // occlude is set per step by the stages
  std::vector<shared::PropagationEntry> entries;
  int steps = 0;
};

// Entry weights: Omega_f / pi (propagate.normalization=energy) or Omega_f / (4 pi) (thesis).
Propagation preparePropagation(const LpvSettings& s, int resolution);

// With lpv.storage=f16, sets params.storage to the power-of-two scale that brings LPV_0's
// largest |coefficient| to at most 1 and rounds `volume` (LPV_0) to half precision in it, as the
// thesis's RGBA16F volumes hold it; with f32, leaves both as they are.
void prepareStorage(const LpvSettings& s, shared::PropagateParams& params,
                    std::vector<float>& volume);

// The GPU's packed form of a volume of `values` stored values a cell under lpv.storage=f16
// (shaders/shared/lpv/storage.h): two halves a word, each cell padded to whole words. Exact both
// ways for values storedValue gave.
std::vector<uint32_t> packStoredVolume(const std::vector<float>& volume, int values,
                                       const shared::PropagateParams& params);
// The `cells` cells of `packed` back into f32 values, `values` a cell, as the words of `out`
// (a buffer's f32 words).
void unpackStoredVolume(const uint32_t* packed, size_t cells, int values,
                        const shared::PropagateParams& params, uint32_t* out);

// Whether step `step` (1 for the step LPV_0 -> LPV_1) is occluded: from the second step on, as
// [Martin 2012, §3.2.3] and Kaplanyan & Dachsbacher do, since the first would block VPLs by their
// own surfaces.
inline bool occludedStep(const LpvSettings& s, int step) {
  return s.occlusion == LpvOcclusion::on && step >= 2;
}

// shade's parameters: 1 / s^2 from the grid's cell size (world units), the RSM's lights
// (analytic lights and area lights, common/lpv/rsm.h) when the rsm stage runs, the camera.
shared::ShadeParams shadeParams(const StageContext& ctx);

}  // namespace voxgi::lpv
