// shared::gatherVoxel (shaders/shared/cone/gather.h) for a batch of voxels at once: every
// voxel's diffuse cone sets are marched together in SIMD lanes (cone_lanes.h), cone by cone so that
// a lane's next cone is its neighbour's and reads nearby texels, then summed per set in the
// kernel's cone order and combined as the kernel combines them. The result is gatherVoxel's, bit
// for bit (tests/svo/propagate_test.cpp), on any lanes.
#pragma once

#include <span>
#include <vector>

#include "cpu/cone/cone_lanes.h"
#include "shaders/shared/cone/gather.h"

namespace voxgi::cpu {

// out[i] = shared::gatherVoxel(volumes, voxels[i], params): `volumes` answers the kernel's
// directAt, albedoAt, normalAt and coneAt; `lanes` is what the cones march through, the same
// pyramid on the lanes of `level`.
template <class Volumes>
void gatherVoxels(SimdLevel level, const Volumes& volumes, const cone_lanes::Volumes& lanes,
                  std::span<const glm::ivec3> voxels, const shared::ConeTraceParams& params,
                  std::span<glm::vec3> out) {
  // Each voxel's sites, and each cone set's start and tangent frame, in voxel order.
  struct Set {
    glm::vec3 origin, n, tangent, bitangent;
  };
  std::vector<shared::GatherSites> sites(voxels.size());
  std::vector<Set> sets;
  for (size_t i = 0; i < voxels.size(); ++i) {
    sites[i] = shared::gatherSites(volumes, voxels[i]);
    for (int side = 0; side < sites[i].sides; ++side) {
      Set set{shared::gatherSideOrigin(sites[i], side, params),
              shared::gatherSideNormal(sites[i], side), glm::vec3(0.0f), glm::vec3(0.0f)};
      shared::tangentFrame(set.n, set.tangent, set.bitangent);
      sets.push_back(set);
    }
  }
  const int coneCount = params.diffuseConeCount;
  std::vector<ConeJob> jobs;
  jobs.reserve(size_t(coneCount) * sets.size());
  for (int c = 0; c < coneCount; ++c) {
    const shared::ConeData cone = volumes.coneAt(c);
    for (const Set& s : sets)
      jobs.push_back({s.origin, shared::diffuseConeDirection(s.tangent, s.bitangent, s.n, cone),
                      cone.direction.z, cone.tanHalfAperture, params.maxDistance});
  }
  std::vector<shared::ConeHit> hits(jobs.size());
  marchCones(level, lanes, jobs, shared::kMarchRadiance, params, hits);

  // Each set's sum in the kernel's cone order, then each voxel's sets combined.
  std::vector<shared::DiffuseSum> sums(sets.size(), shared::noDiffuse());
  for (int c = 0; c < coneCount; ++c) {
    const shared::ConeData cone = volumes.coneAt(c);
    for (size_t k = 0; k < sets.size(); ++k)
      sums[k] = shared::addDiffuseCone(sums[k], hits[size_t(c) * sets.size() + k], cone);
  }
  size_t k = 0;
  for (size_t i = 0; i < voxels.size(); ++i) {
    const shared::GatherSites& g = sites[i];
    if (g.sides == 0) {
      out[i] = glm::vec3(0.0f);
      continue;
    }
    const glm::vec3 first = sums[k++].radiance;
    const glm::vec3 second = g.sides == 2 ? sums[k++].radiance : glm::vec3(0.0f);
    out[i] = shared::gatheredLight(g, first, second);
  }
}

}  // namespace voxgi::cpu
