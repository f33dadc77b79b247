// The CPU's fast path for shared::voxelVisibility (voxel_light.h): a stream of visibility
// rays marched several at a time, one per SIMD lane (xsimd, the widest lanes this CPU runs,
// cpu/simd.h), a lane whose ray ends taking the next. Each step's position, voxel and bounds run
// in the lanes, and so does the test of a map of the voxels that may be opaque; only a voxel the
// map marks is read and composited, on its own lane. The same operations in the same order as the
// kernel, so the same visibility bit for bit (tests/cone/shadow_lanes_test.cpp).
#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "cpu/simd.h"

namespace voxgi::cpu {

// One ray: voxelVisibility's march after its set-up.
struct ShadowRay {
  glm::vec3 origin;   // shared::shadowRayOrigin
  glm::vec3 toLight;  // unit
  float limit;        // the march stops at the first step t >= limit (distance - offset)
};

// What the rays march through: a grid of n voxels a side (n <= 1024).
struct ShadowVolume {
  int n;
  int maxSteps;  // shared::shadowRayMaxSteps(n)
  // Bit shared::mortonEncode(v) of the words set wherever voxel v's opacity may be above 0 (every
  // voxel whose opacity is): the other voxels' steps read nothing.
  const uint32_t* mayBeOpaque;
  // The occlusion after step t meets voxel (x, y, z), whose bit is set: shared::shadowCollision
  // with its opacity, or `occlusion` where that is 0.
  float (*collide)(const void* context, int x, int y, int z, float t, float occlusion);
  const void* context;
};

// visibility[i] = shared::voxelVisibility of rays[i] (under a voxel_shadow.mode other than none),
// bit for bit, on the lanes of `level`, which this CPU must run.
void marchShadowRays(SimdLevel level, const ShadowVolume& volume, std::span<const ShadowRay> rays,
                     std::span<float> visibility);

// Each instruction set's march (shadow_lanes_impl.h), for the dispatch above; like the cone lanes,
// they call no inline function another unit shares.
namespace shadow_lanes {
void marchShadowRaysSse2(const ShadowVolume& volume, std::span<const ShadowRay> rays,
                         std::span<float> visibility);
void marchShadowRaysAvx2(const ShadowVolume& volume, std::span<const ShadowRay> rays,
                         std::span<float> visibility);
void marchShadowRaysAvx512(const ShadowVolume& volume, std::span<const ShadowRay> rays,
                           std::span<float> visibility);
}  // namespace shadow_lanes

}  // namespace voxgi::cpu
