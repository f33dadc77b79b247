// The cone tracer's FETCH(pyramidAt) for trace_cones and bounce: level 0 is the radiance volume,
// level l the pyramid texture's level l - 1, faces side by side along x (common/mips.h). Read with
// texelFetch: trilinear and level blending happen in the shared code, so both backends filter
// identically.
layout(binding = 0) uniform sampler3D uRadiance;
layout(binding = 1) uniform sampler3D uPyramid;
layout(location = 0) uniform int uResolution;

vec4 pyramidAt(int level, int face, ivec3 v) {
  if (level == 0) return texelFetch(uRadiance, v, 0);
  int s = uResolution >> level;
  return texelFetch(uPyramid, ivec3(v.x + face * s, v.y, v.z), level - 1);
}

// The GPU reads empty cells through its texture cache; the CPU skips them with an occupancy
// bitmask (cpu/cone/cell_occupancy.h), which gives the same +0.
bool cellEmpty(int level, ivec3 i) { return false; }
