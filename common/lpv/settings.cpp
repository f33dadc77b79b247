// Light propagation volumes' --set keys, presets and the holpv variant.
#include "common/technique.h"

namespace voxgi::lpv {

const std::vector<Param>& params() {
  constexpr auto lpv = &Settings::lpv;
  static const std::vector<Param> table = [] {
    std::vector<Param> out{
        number<lpv>("lpv.bands", &LpvSettings::bands, 2, 3,
                    "SH bands per colour: 2 (4 coefficients, LPV) or 3 (9, HOLPV)"),
        choice<lpv>("lpv.storage", &LpvSettings::storage, {"f32", "f16"},
                    "precision of the stored volumes: f32, or f16 as the thesis's RGBA16F (each "
                    "step and the accumulation rounded to half)"),
        choice<lpv>("propagate.directions", &LpvSettings::directions, {"6", "26"},
                    "neighbours light propagates to per step: the 6 face neighbours (30 face "
                    "entries) or all 26 (54)"),
        number<lpv>("propagate.steps", &LpvSettings::steps, 0, 1024,
                    "propagation steps; 0: half the grid's resolution (voxgi plan says why)"),
        choice<lpv>("propagate.normalization", &LpvSettings::normalization, {"energy", "thesis"},
                    "per-face weight Omega/pi (conserves flux) or Omega/(4 pi) as Martin's Eq. 3.3 "
                    "prints it (keeps 1/4 per step)"),
        choice<lpv>("propagate.clamp", &LpvSettings::clampNegative, {"off", "on"},
                    "clamp each face's intensity at 0 before it is re-emitted (not linear)"),
        choice<lpv>("propagate.occlusion", &LpvSettings::occlusion, {"off", "on"},
                    "attenuate by the geometry volume from the second step on"),
        choice<lpv>("propagate.accumulate_injection", &LpvSettings::accumulateInjection,
                    {"off", "on"}, "the accumulated volume includes the injected one (LPV_0)"),
        choice<lpv>("propagate.history", &LpvSettings::history, {"off", "on"},
                    "keep every step's volume (propagate.steps_sh4|sh9; voxgi diff and dump turn "
                    "it on)"),
        number<lpv>("inject.emitter_spacing", &LpvSettings::emitterSpacing, 0.01f, 8.0f,
                    "spacing of the VPLs sampled on emissive triangles, in cells"),
        choice<lpv>("inject.shift", &LpvSettings::vplShift, {"off", "on"},
                    "move each VPL half a cell along its normal before binning (self-lighting)"),
        choice<lpv>(
            "inject_geometry.blockers", &LpvSettings::geometry, {"voxels", "rsm"},
            "the geometry volume's blockers: voxelize's surface area and normals per voxel, "
            "or the surfaces the analytic lights' RSM texels see (the light seeing most of a "
            "cell wins)"),
        number<lpv>("shade.offset", &LpvSettings::shadeOffset, 0.0f, 2.0f,
                    "cells along the normal at which a pixel samples the accumulated volume"),
        number<lpv>(
            "rsm.resolution", &LpvSettings::rsmResolution, 1, 4096,
            "texels per side of a reflective shadow map view (six views for a point light)"),
        number<lpv>("rsm.bias", &LpvSettings::rsmBias, 0.0f, 16.0f,
                    "shadow-map depth bias in texel footprints, divided by the surface's cosine"),
    };
    // Voxel cone tracing's emitters.mode (Settings::vct): whether emissive triangles are area
    // lights (direct light per pixel, their reflective shadow maps' texels the volume's VPLs) or
    // VPLs of their own in the volume, as [Martin 2012] injects them.
    for (Param& p : vct::kernelParams({"emitters"})) out.push_back(std::move(p));
    return out;
  }();
  return table;
}

const std::vector<Preset>& presets() {
  // martin2012: the thesis's form, the emitters' own VPLs carrying their direct light through the
  // volume [Martin 2012, §3.2.1]; its per-scene steps and occlusion are set per scene
  // (docs/lpv.md).
  static const std::vector<Preset> table{{"default", {}}, {"martin2012", {"emitters.mode=voxels"}}};
  return table;
}

const std::vector<Variant>& variants() {
  static const std::vector<Variant> table{
      {"holpv",
       "higher-order light propagation volumes [Martin 2012]: lpv with 3 SH bands and 26 "
       "propagation directions",
       {"lpv.bands=3", "propagate.directions=26"}},
  };
  return table;
}

}  // namespace voxgi::lpv
