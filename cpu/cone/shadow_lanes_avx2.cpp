// shadow_lanes.h's march on AVX2 (8 lanes a batch), built with -mavx2 alone (cpu/CMakeLists.txt);
// only shadow_lanes.cpp's dispatch calls it, on a CPU that has AVX2.
#define VOXGI_LANES_ARCH xsimd::avx2
#define VOXGI_SHADOW_LANES_SUFFIX Avx2
#define VOXGI_LANES_BITS(mask) _mm256_movemask_ps(mask)
#include "cpu/cone/shadow_lanes_impl.h"
