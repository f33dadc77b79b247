// cone_lanes.h's march on AVX-512F (16 lanes a batch), built with -mavx512f alone
// (cpu/CMakeLists.txt). Only cone_lanes.cpp's dispatch calls it, on a CPU that has AVX-512F. A
// mask is a mask register there: its bits are the lanes'.
// GCC 12's avx512fintrin.h passes a deliberately undefined register (_mm512_undefined_*) as the
// unused source of the unmasked conversions and shifts xsimd calls, which -Wmaybe-uninitialized
// (and, in the sanitizer builds, -Wuninitialized) reports in the header; no value of it reaches a
// lane.
#if defined(__GNUC__) && !defined(__clang__)  // clang has no -Wmaybe-uninitialized, nor this case
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#define VOXGI_LANES_ARCH xsimd::avx512f
#define VOXGI_CONE_LANES_SUFFIX Avx512
#define VOXGI_LANES_BITS(mask) __mmask16(mask)
#include "cpu/cone/cone_lanes_impl.h"
