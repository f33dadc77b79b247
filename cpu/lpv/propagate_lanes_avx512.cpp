// propagate_lanes.h on AVX-512F (16 lanes, 32 registers), built with -mavx512f alone
// (cpu/CMakeLists.txt): no FMA, so no contraction. Only cpu/simd.h's dispatch calls it, on a CPU
// that has AVX-512F.
#define VOXGI_LANES_ARCH xsimd::avx512f
#define VOXGI_LANES_SUFFIX Avx512
#include "cpu/lpv/propagate_lanes_impl.h"
