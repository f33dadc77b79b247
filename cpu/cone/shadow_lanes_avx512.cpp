// shadow_lanes.h's march on AVX-512F (16 lanes a batch), built with -mavx512f alone
// (cpu/CMakeLists.txt); only shadow_lanes.cpp's dispatch calls it, on a CPU that has AVX-512F.
// GCC 12's avx512fintrin.h passes a deliberately undefined register as the unused source of the
// unmasked conversions and shifts xsimd calls (cone_lanes_avx512.cpp); no value of it reaches a
// lane.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#define VOXGI_LANES_ARCH xsimd::avx512f
#define VOXGI_SHADOW_LANES_SUFFIX Avx512
#define VOXGI_LANES_BITS(mask) __mmask16(mask)
#include "cpu/cone/shadow_lanes_impl.h"
