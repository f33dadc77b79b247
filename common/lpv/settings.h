// Light propagation volumes' parameters (Settings::lpv), with their defaults. The keys, ranges and
// meanings are in common/lpv/settings.cpp, with the presets and the holpv variant.
#pragma once

namespace voxgi {

enum class LpvDirections {
  six,
  twenty_six
};  // [Kaplanyan & Dachsbacher 2010]; [Martin 2012, §4.2]
// energy: per-face weight Omega/pi, which conserves flux; thesis: Eq. 3.3 as printed, Omega/(4 pi),
// which keeps a quarter per step [Martin 2012, §3.2.3] (docs/lpv.md)
enum class LpvNormalization { energy, thesis };
enum class LpvOcclusion { off, on };
enum class LpvToggle { off, on };
// Where the geometry volume's blockers come from: voxelize's surface sums, or the RSM texels.
enum class LpvGeometry { voxels, rsm };
// The precision the volumes are stored in: f32, or f16 as the thesis's RGBA16F [Martin 2012, §5.8].
enum class LpvStorage { f32, f16 };

struct LpvSettings {
  LpvStorage storage = LpvStorage::f32;           // precision of the stored volumes
  int bands = 2;                                  // SH bands per colour: 2 (4 coeffs) or 3 (9)
  LpvDirections directions = LpvDirections::six;  // propagate
  int steps = 0;                                  // 0: half the grid's resolution (the planner)
  LpvNormalization normalization = LpvNormalization::energy;
  LpvToggle clampNegative = LpvToggle::off;  // clamp each face's intensity at 0 (breaks linearity)
  LpvOcclusion occlusion = LpvOcclusion::on;
  LpvToggle accumulateInjection = LpvToggle::on;  // the accumulated volume includes LPV_0 (A9)
  LpvToggle history = LpvToggle::off;             // keep every step's volume
  float emitterSpacing = 0.25f;         // emitter VPL spacing along a triangle's edges, in cells
  LpvToggle vplShift = LpvToggle::off;  // move each VPL half a cell along its normal before binning
  float shadeOffset = 0.0f;             // cells along the normal where shade samples the volume
  LpvGeometry geometry = LpvGeometry::voxels;  // inject_geometry's source
  int rsmResolution = 256;                     // texels per side of each reflective shadow map view
  float rsmBias = 1.5f;  // shadow-map depth bias, in texel footprints / cosine

  int coefficients() const { return bands * bands; }
  int directionCount() const { return directions == LpvDirections::six ? 6 : 26; }
};

}  // namespace voxgi
