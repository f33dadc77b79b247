// shared::lightVoxel (shaders/shared/cone/voxel_light.h) for a batch of voxels at once:
// every voxel's light terms first, then all their visibility rays marched together in SIMD lanes
// (shadow_lanes.h), then each voxel's shares summed in the kernel's light order. The result is
// lightVoxel's, bit for bit (tests/cone/shadow_lanes_test.cpp, tests/svo/propagate_test.cpp).
#pragma once

#include <span>
#include <vector>

#include "cpu/cone/shadow_lanes.h"
#include "shaders/shared/cone/voxel_light.h"

namespace voxgi::cpu {

// The rays' view of `volumes` (which answer opacityAt) under `params`: a ShadowVolume whose
// collisions are shared::shadowCollision's. Must outlive the ShadowVolume it makes.
template <class Volumes>
struct ShadowRays {
  const Volumes* volumes;
  const shared::LightVoxelsParams* params;

  static float collide(const void* context, int x, int y, int z, float t, float occlusion) {
    const ShadowRays& r = *static_cast<const ShadowRays*>(context);
    const float a = r.volumes->opacityAt({x, y, z});
    return a <= 0.0f ? occlusion : shared::shadowCollision(occlusion, a, t, *r.params);
  }
  // `map`: ShadowVolume::mayBeOpaque over params->resolution voxels a side.
  ShadowVolume volume(const uint32_t* map) const {
    const int n = params->resolution;
    return {n, shared::shadowRayMaxSteps(n), map, collide, this};
  }
};

// out[i] = shared::lightVoxel(volumes, voxels[i], params): `volumes` answers the kernel's
// opacityAt, albedoAt, normalAt, emissionAt and lightAt; `shadow` is its opacity as the rays
// march it.
template <class Volumes>
void lightVoxels(SimdLevel level, const Volumes& volumes, const ShadowVolume& shadow,
                 std::span<const glm::ivec3> voxels, const shared::LightVoxelsParams& params,
                 std::span<glm::vec4> out) {
  // Each lit voxel's attributes, and each light's share of it with its ray (-1: none).
  struct Lit {
    size_t voxel;
    float a;
    glm::vec3 albedo;
    size_t firstShare, endShare;
  };
  struct Share {
    shared::LightTerm term;
    float scale;
    long ray;
  };
  std::vector<Lit> lit;
  std::vector<Share> shares;
  std::vector<ShadowRay> rays;
  const bool marched = params.voxelShadow != shared::kVoxelShadowNone;
  for (size_t i = 0; i < voxels.size(); ++i) {
    const glm::ivec3 v = voxels[i];
    out[i] = glm::vec4(0.0f);
    const float a = volumes.opacityAt(v);
    if (a <= 0.0f) continue;
    const glm::vec3 n = shared::normalize3(volumes.normalAt(v));
    const glm::vec3 p = glm::vec3(v) + glm::vec3(0.5f);
    Lit l{i, a, volumes.albedoAt(v), shares.size(), 0};
    for (int k = 0; k < params.lightCount; ++k) {
      Share s{};
      s.scale = shared::lightTerm(volumes.lightAt(k), p, n, params, s.term);
      if (s.scale <= 0.0f) continue;
      s.ray = -1;
      if (s.term.shadowed && marched) {
        s.ray = long(rays.size());
        rays.push_back({shared::shadowRayOrigin(p, s.term.rayNormal, params), s.term.toLight,
                        s.term.rayLength - params.shadowOffset});
      }
      shares.push_back(s);
    }
    l.endShare = shares.size();
    lit.push_back(l);
  }
  std::vector<float> visibility(rays.size());
  marchShadowRays(level, shadow, rays, visibility);
  for (const Lit& l : lit) {
    glm::vec3 irradiance(0.0f);
    for (size_t s = l.firstShare; s < l.endShare; ++s) {
      const Share& share = shares[s];
      const float vis = share.ray >= 0 ? visibility[size_t(share.ray)] : 1.0f;
      irradiance = shared::addLightShare(irradiance, share.term, share.scale, vis);
    }
    out[l.voxel] =
        shared::voxelRadiance(volumes, voxels[l.voxel], l.a, l.albedo, irradiance, params);
  }
}

}  // namespace voxgi::cpu
