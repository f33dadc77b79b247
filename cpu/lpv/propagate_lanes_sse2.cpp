// propagate_lanes.h on SSE2, which every x86-64 CPU runs.
#define VOXGI_LANES_ARCH xsimd::sse2
#define VOXGI_LANES_SUFFIX Sse2
#include "cpu/lpv/propagate_lanes_impl.h"
