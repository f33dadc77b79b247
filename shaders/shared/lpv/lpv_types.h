// Records the host and both light-propagation-volume backends share (std430), and the fixed-point
// format of injection. Included by C++ and GLSL.
#ifndef VOXGI_LPV_TYPES_H
#define VOXGI_LPV_TYPES_H
#include "../glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// A virtual point light (common/lpv/inject.cpp): a clamped-cosine emitter of flux `flux`
// about `normal`, binned into the cell that holds `position`. 48 bytes.
struct Vpl {
  vec4 position;  // xyz: voxel-local position (after inject.shift); w: 0
  vec4 normal;    // xyz: unit normal; w: 0
  vec4 flux;      // rgb: flux (world units: radiance x area x pi); w: 0
};

// inject's block: the VPLs follow it.
struct InjectParams {
  ivec4 shape;  // x: grid resolution N; y: SH coefficients per colour C; z: VPL count; w: 1 to
                // shift the RSM texels' VPLs (inject.shift; the emitters' are shifted on the host)
  vec4 scale;   // rgb: fixed-point units per unit of intensity (powers of two); w: 0
};

// One face entry of a propagation step (common/lpv/propagate.cpp), for a destination cell
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
  vec4 storage;   // x: 1 to round stored values to half precision (lpv.storage=f16); y: the
                  // power-of-two scale they are stored in units of; z: 1 / y; w: 0
};

// One view of a reflective shadow map (common/lpv/rsm.cpp): a cube face of a point light (or of a
// spot wider than 120 degrees), a spot's frustum, or a directional light's orthographic box. Its
// rsm.resolution^2 texels are rows of texel rays, row 0 at the top as the camera's. 80 bytes.
struct RsmView {
  vec4 origin;   // xyz: voxel-local position (the light; a directional view's corner plane centre)
                 // w: 1 perspective, 0 orthographic
  vec4 forward;  // xyz: unit view axis; w: tan(half field of view) or the box's half width (cells)
  vec4 right;    // xyz: unit
  vec4 up;       // xyz: unit
  ivec4 info;    // x: light index; y: the light's first view; z: its view count (1 or 6); w: 0
};

// The rsm stage's block: the views follow it.
struct RsmParams {
  ivec4 shape;  // x: rsm.resolution R; y: view count; z: light count; w: 0
  vec4 scale;   // x: voxel size (world units); y: rsm.bias in texels; zw: 0
};

// shade's uniforms.
struct ShadeParams {
  ivec4 shape;  // x: N; y: C; z: analytic light count (direct light from the RSM); w: 0
  vec4 scale;   // x: 1 / (cell size^2) (world units); y: shade.offset in cells; zw: 0
  vec4 camera;  // xyz: voxel-local camera position (the specular lobe's view direction)
};

VOXGI_NAMESPACE_END
#endif
