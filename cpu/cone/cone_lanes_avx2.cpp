// cone_lanes.h's march on AVX2 (8 lanes a batch), built with -mavx2 alone (cpu/CMakeLists.txt):
// no FMA, so no contraction either way. Only cone_lanes.cpp's dispatch calls it, on a CPU that has
// AVX2.
#define VOXGI_LANES_ARCH xsimd::avx2
#define VOXGI_CONE_LANES_SUFFIX Avx2
#define VOXGI_LANES_BITS(mask) _mm256_movemask_ps(mask)
#include "cpu/cone/cone_lanes_impl.h"
