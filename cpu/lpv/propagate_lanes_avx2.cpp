// propagate_lanes.h on AVX2 (8 lanes), built with -mavx2 alone (cpu/CMakeLists.txt): no FMA, so
// no contraction either way. Only cpu/simd.h's dispatch calls it, on a CPU that has AVX2.
#define VOXGI_LANES_ARCH xsimd::avx2
#define VOXGI_LANES_SUFFIX Avx2
#include "cpu/lpv/propagate_lanes_impl.h"
