// Records the host and both light-propagation-volume backends share (std430), and the fixed-point
// format of injection. Included by C++ and GLSL.
#ifndef VOXGI_LPV_TYPES_H
#define VOXGI_LPV_TYPES_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// A virtual point light (common/lpv/injection.cpp): a clamped-cosine emitter of flux `flux`
// about `normal`, binned into the cell that holds `position`. 48 bytes.
struct Vpl {
  vec4 position;  // xyz: voxel-local position (after inject.shift); w: 0
  vec4 normal;    // xyz: unit normal; w: 0
  vec4 flux;      // rgb: flux (world units: radiance x area x pi); w: 0
};

// inject_lpv's block: the VPLs follow it.
struct InjectParams {
  ivec4 shape;  // x: grid resolution N; y: SH coefficients per colour C; z: VPL count; w: 0
  vec4 scale;   // rgb: fixed-point units per unit of intensity (powers of two); w: 0
};

// One face entry of a propagation step (common/lpv/propagation.cpp), for a destination cell
// whose source is the cell at -offset. 112 bytes.
struct PropagationEntry {
  ivec4 offset;          // xyz: destination - source; w: 0
  float sampled[9];      // Y_i(omega_f): the source's intensity toward the face's centre
  float reprojected[9];  // weight x A_l Y_i(n_f): the lobe the face re-emits, per unit intensity
  float blocking[4];     // Y_i(-omega_f): the geometry volume's blocking against this direction
  float pad[2];
};

// propagate's block: the entries follow it.
struct PropagateParams {
  ivec4 shape;    // x: N; y: C; z: entry count; w: 1 to occlude (from the second step on)
  ivec4 options;  // x: 1 to clamp each face's intensity at 0; yzw: 0
};

// shade_lpv's uniforms.
struct ShadeParams {
  ivec4 shape;  // x: N; y: C; zw: 0
  vec4 scale;   // x: 1 / (cell size^2) (world units); y: shade.offset in cells; zw: 0
};

VOXGI_NAMESPACE_END
#endif
