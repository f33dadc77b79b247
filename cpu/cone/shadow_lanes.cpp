// marchShadowRays on the lanes asked for (cpu/simd.h): every level computes the same bits.
#include "cpu/cone/shadow_lanes.h"

namespace voxgi::cpu {

void marchShadowRays(SimdLevel level, const ShadowVolume& volume, std::span<const ShadowRay> rays,
                     std::span<float> visibility) {
  switch (level) {
    case SimdLevel::avx512:
      return shadow_lanes::marchShadowRaysAvx512(volume, rays, visibility);
    case SimdLevel::avx2:
      return shadow_lanes::marchShadowRaysAvx2(volume, rays, visibility);
    case SimdLevel::sse2:
      break;
  }
  shadow_lanes::marchShadowRaysSse2(volume, rays, visibility);
}

}  // namespace voxgi::cpu
