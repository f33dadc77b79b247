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
  int resolution;    // the grid's N
  int coefficients;  // SH coefficients per colour C
  int vplCount;
  int shiftRsmVpls;  // 1 to shift the RSM texels' VPLs (inject.shift; the emitters' are shifted on
                     // the host)
  vec4 scale;        // rgb: fixed-point units per unit of intensity (powers of two); w: 0
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
  int resolution;    // N
  int coefficients;  // C
  int entryCount;
  int occlude;                // 1 to occlude (from the second step on)
  int clampNegative;          // 1 to clamp each face's intensity at 0
  int halfPrecision;          // 1 to round stored values to half precision (lpv.storage=f16)
  float storageScale;         // the power-of-two scale they are stored in units of
  float inverseStorageScale;  // 1 / storageScale
};

// One view of a reflective shadow map (common/lpv/rsm.cpp): a cube face of a point light (or of a
// spot wider than 120 degrees), a spot's frustum, or a directional light's orthographic box. Its
// rsm.resolution^2 texels are rows of texel rays, row 0 at the top as the camera's. 80 bytes.
struct RsmView {
  vec3 origin;      // voxel-local position (the light; a directional view's corner plane centre)
  int perspective;  // 1 perspective, 0 orthographic
  vec3 forward;     // unit view axis
  float extent;     // tan(half field of view), or the orthographic box's half width (cells)
  vec3 right;       // unit
  float pad0;
  vec3 up;  // unit
  float pad1;
  int light;      // index into the lights
  int firstView;  // the light's first view (host only)
  int viewCount;  // the light's views: 1, or 6 for a point light's cube (host only)
  int pad2;
};

// The rsm stage's block: the views follow it.
struct RsmParams {
  int resolution;  // rsm.resolution R
  int viewCount;
  int lightCount;
  int pad0;
  float voxelSize;   // world units
  float biasTexels;  // rsm.bias
  float pad1;
  float pad2;
};

// shade's uniforms.
struct ShadeParams {
  int resolution;    // N
  int coefficients;  // C
  int lightCount;    // analytic lights (direct light from the RSM)
  int pad0;
  float inverseCellArea;  // 1 / (cell size^2) (world units)
  float offsetCells;      // shade.offset
  float pad1;
  float pad2;
  vec4 camera;  // xyz: voxel-local camera position (the specular lobe's view direction)
};

VOXGI_NAMESPACE_END
#endif
