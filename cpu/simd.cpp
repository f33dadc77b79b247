#include "cpu/simd.h"

#include <cstdlib>
#include <cstring>

namespace voxgi::cpu {

SimdLevel detectedSimdLevel() {
  // GCC's and Clang's CPUID check: also false where the OS does not save the AVX registers.
  if (__builtin_cpu_supports("avx512f")) return SimdLevel::avx512;
  return __builtin_cpu_supports("avx2") ? SimdLevel::avx2 : SimdLevel::sse2;
}

SimdLevel simdLevel() {
  static const SimdLevel level = [] {
    const char* forced = std::getenv("VOXGI_SIMD");
    const SimdLevel detected = detectedSimdLevel();
    if (forced && std::strcmp(forced, "sse2") == 0) return SimdLevel::sse2;
    if (forced && std::strcmp(forced, "avx2") == 0 && detected == SimdLevel::avx512)
      return SimdLevel::avx2;
    return detected;
  }();
  return level;
}

std::vector<SimdLevel> runnableSimdLevels() {
  std::vector<SimdLevel> levels;
  for (int l = 0; l <= int(detectedSimdLevel()); ++l) levels.push_back(SimdLevel(l));
  return levels;
}

std::string_view simdLevelName(SimdLevel level) {
  constexpr std::string_view kNames[] = {"sse2", "avx2", "avx512"};  // SimdLevel's order
  return kNames[int(level)];
}

}  // namespace voxgi::cpu
