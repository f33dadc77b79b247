// Accumulation targets of the voxelize stage (fragment and compute variants). The multi-component
// sums are stored x-interleaved in 3N x N x N images (4N for the emission and the emitters'
// weight): texel (3i + c, j, k) holds component c of voxel (i, j, k), which is exactly the CPU
// buffer layout, so readback needs no reshuffling.
layout(std430, binding = 0) readonly buffer Triangles { VoxelTriangle triangles[]; };
layout(std430, binding = 1) buffer Status { uint overflow; };
layout(binding = 0, r32ui) uniform coherent uimage3D uWeightSum;
layout(binding = 1, r32ui) uniform coherent uimage3D uAlbedoSum;
layout(binding = 2, r32i) uniform coherent iimage3D uNormalSum;
layout(binding = 3, r32ui) uniform coherent uimage3D uEmissionSum;
uniform int uResolution;
uniform bool uHasEmission;  // false: the scene emits nothing and uEmissionSum is not bound
// A partial update (common/voxelize_update.h) takes the frame before's contributions of the moved
// meshes out: adding 0 - v modulo 2^32 is exact.
uniform bool uSubtract;

uint term(uint v) { return uSubtract ? 0u - v : v; }

void accumulate(ivec3 voxel, VoxelContribution c) {
  uint old = imageAtomicAdd(uWeightSum, voxel, term(c.weight));
  if (!uSubtract && old > 0xFFFFFFFFu - c.weight) atomicOr(overflow, 1u);
  for (int i = 0; i < 3; ++i) {
    ivec3 texel = ivec3(3 * voxel.x + i, voxel.y, voxel.z);
    imageAtomicAdd(uAlbedoSum, texel, term(c.albedo[i]));
    imageAtomicAdd(uNormalSum, texel, int(term(uint(c.normal[i]))));
    if (uHasEmission)
      imageAtomicAdd(uEmissionSum, ivec3(4 * voxel.x + i, voxel.y, voxel.z), term(c.emission[i]));
  }
  if (uHasEmission)
    imageAtomicAdd(uEmissionSum, ivec3(4 * voxel.x + 3, voxel.y, voxel.z), term(c.emitterWeight));
}
