// marchCones on the widest lanes this CPU runs (cpu/simd.h): the levels compute the same bits.
#include "cpu/cone/cone_lanes.h"

namespace voxgi::cpu {

cone_lanes::Volumes laneVolumes(const ConeVolumes& cone) {
  cone_lanes::Volumes volumes{{}, {}, {}, cone.faces, cone.n};
  for (int l = 0; l < 16; ++l) {
    volumes.levels[l] = cone.levels[l];
    volumes.occupied[l] = cone.occupancy[l].bits();
    volumes.occupiedSide[l] = cone.occupancy[l].side();
  }
  return volumes;
}

void marchCones(SimdLevel level, const ConeVolumes& cone, std::span<const ConeJob> jobs, int kind,
                const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits) {
  marchCones(level, laneVolumes(cone), jobs, kind, params, hits);
}

void marchCones(SimdLevel level, const cone_lanes::Volumes& volumes, std::span<const ConeJob> jobs,
                int kind, const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits) {
  switch (level) {
    case SimdLevel::avx512:
      return cone_lanes::marchConesAvx512(volumes, jobs, kind, params, hits);
    case SimdLevel::avx2:
      return cone_lanes::marchConesAvx2(volumes, jobs, kind, params, hits);
    case SimdLevel::sse2:
      break;
  }
  cone_lanes::marchConesSse2(volumes, jobs, kind, params, hits);
}

void marchCones(const ConeVolumes& volumes, std::span<const ConeJob> jobs, int kind,
                const shared::ConeTraceParams& params, std::span<shared::ConeHit> hits) {
  marchCones(simdLevel(), volumes, jobs, kind, params, hits);
}

}  // namespace voxgi::cpu
