// shared::gatherVoxel (shaders/shared/vct/bounce_kernel.h) for a batch of voxels at once: every
// voxel's diffuse cone sets are marched together in SIMD lanes (cone_lanes.h), cone by cone so that
// a lane's next cone is its neighbour's and reads nearby texels, then summed per set in the
// kernel's cone order and combined as the kernel combines them. The result is gatherVoxel's, bit
// for bit (tests/svo/propagate_test.cpp), on any lanes.
#pragma once

#include <span>
#include <vector>

#include "cpu/vct/cone_lanes.h"
#include "shaders/shared/vct/bounce_kernel.h"

namespace voxgi::cpu {

// What gatherVoxels keeps between batches, so that a task allocates once.
struct GatherScratch {
  std::vector<shared::GatherSites> sites;
  struct Set {
    size_t voxel;
    glm::vec3 origin, n, tangent, bitangent;
  };
  std::vector<Set> sets;
  std::vector<ConeJob> jobs;
  std::vector<shared::ConeHit> hits;
  std::vector<shared::DiffuseSum> sums;
};

// out[i] = shared::gatherVoxel(volumes, voxels[i], params): `volumes` answers the kernel's
// directAt, albedoAt, normalAt and coneAt; `lanes` is what the cones march through, the same
// pyramid on the lanes of `level`.
template <class Volumes>
void gatherVoxels(SimdLevel level, const Volumes& volumes, const cone_lanes::Volumes& lanes,
                  std::span<const glm::ivec3> voxels, const shared::ConeTraceParams& params,
                  std::span<glm::vec3> out, GatherScratch& scratch) {
  scratch.sites.resize(voxels.size());
  scratch.sets.clear();
  for (size_t i = 0; i < voxels.size(); ++i) {
    const shared::GatherSites g = shared::gatherSites(volumes, voxels[i]);
    scratch.sites[i] = g;
    for (int side = 0; side < g.sides; ++side) {
      GatherScratch::Set set{i, shared::gatherSideOrigin(g, side, params),
                             shared::gatherSideNormal(g, side), glm::vec3(0.0f), glm::vec3(0.0f)};
      shared::tangentFrame(set.n, set.tangent, set.bitangent);
      scratch.sets.push_back(set);
    }
  }
  const size_t sets = scratch.sets.size();
  const int coneCount = params.diffuseConeCount;
  scratch.jobs.clear();
  for (int c = 0; c < coneCount; ++c) {
    const shared::ConeData cone = volumes.coneAt(c);
    for (const GatherScratch::Set& s : scratch.sets)
      scratch.jobs.push_back({s.origin,
                              shared::diffuseConeDirection(s.tangent, s.bitangent, s.n, cone),
                              cone.direction.z, cone.tanHalfAperture, params.maxDistance});
  }
  scratch.hits.resize(scratch.jobs.size());
  marchCones(level, lanes, scratch.jobs, shared::kMarchRadiance, params, scratch.hits);

  // Each set's sum in the kernel's cone order, then each voxel's sets combined.
  std::vector<shared::DiffuseSum>& sums = scratch.sums;
  sums.assign(sets, shared::noDiffuse());
  for (int c = 0; c < coneCount; ++c) {
    const shared::ConeData cone = volumes.coneAt(c);
    for (size_t k = 0; k < sets; ++k)
      sums[k] = shared::addDiffuseCone(sums[k], scratch.hits[size_t(c) * sets + k], cone);
  }
  size_t k = 0;
  for (size_t i = 0; i < voxels.size(); ++i) {
    const shared::GatherSites& g = scratch.sites[i];
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
