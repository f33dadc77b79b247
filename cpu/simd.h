// Which SIMD instruction set the CPU backend's lanes use: the best this CPU runs (AVX-512F, AVX2
// or SSE2, from CPUID and the OS's saving of the wide registers), lowered by the environment's
// VOXGI_SIMD=sse2 or VOXGI_SIMD=avx2 (to compare the paths, or to rule the wider ones out; it never
// raises the level). Code built for AVX2 or AVX-512 lives in translation units of its own
// (cpu/*/*_avx2.cpp, *_avx512.cpp, the voxgi_cpu_wide objects) and is reached only after a check
// of simdLevel(). Every level computes the same bits.
#pragma once

#include <string_view>
#include <vector>

namespace voxgi::cpu {

enum class SimdLevel { sse2, avx2, avx512 };  // in order: each runs where the next does

// What the CPU supports, whatever the environment says.
SimdLevel detectedSimdLevel();
// What the lanes use: detectedSimdLevel(), lowered by VOXGI_SIMD (read once).
SimdLevel simdLevel();
std::string_view simdLevelName(SimdLevel level);
// Every level this CPU runs, SSE2 first (tests compare them).
std::vector<SimdLevel> runnableSimdLevels();

}  // namespace voxgi::cpu
