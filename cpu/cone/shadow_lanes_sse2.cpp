// shadow_lanes.h's march on SSE2 (4 lanes a batch), what every x86-64 runs.
#define VOXGI_LANES_ARCH xsimd::sse2
#define VOXGI_SHADOW_LANES_SUFFIX Sse2
#define VOXGI_LANES_BITS(mask) _mm_movemask_ps(mask)
#include "cpu/cone/shadow_lanes_impl.h"
