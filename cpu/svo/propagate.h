// svo's propagate on the CPU (docs/stages/svo/propagate.md): the light injected into the leaves,
// then propagate.frames progressive bounces, each a gather of the cone library's diffuse cones at
// every real leaf over the mipmap of the frame before. The twin of gpu/svo/propagate.h, shaped
// alike: injectLeaves, bounceOnce, propagateFrames.
#pragma once

#include <vector>

#include "cpu/simd.h"
#include "cpu/svo/svo_volumes.h"
#include "shaders/shared/cone/cone_types.h"
#include "shaders/shared/cone/voxel_light.h"

namespace voxgi::cpu::svo {

// Radiance the leaves send out before any bounce: emission plus the analytic lights' diffuse
// reflection with the voxel visibility of voxel_light.h, premultiplied by the clamped
// opacity. Up to depth 9 the visibility rays run in the lanes of `level` (voxel_light_lanes.h);
// every level gives lightVoxel's bits.
LeafRadiance injectLeaves(const Octree& octree, const Leaves& leaves,
                          const std::vector<shared::LightData>& lights,
                          const shared::LightVoxelsParams& params, SimdLevel level = simdLevel());

// One gather at every real leaf (gather.h): direct + albedo x the diffuse cones over the
// mipmap of `source`.
LeafRadiance bounceOnce(const Octree& octree, const Leaves& leaves, const LeafRadiance& direct,
                        const LeafRadiance& source, const std::vector<shared::ConeData>& cones,
                        const shared::ConeTraceParams& params, FirstStep first,
                        FrameOutputs* outputs = nullptr);

// `frames` progressive bounces [Salm 2015, §4.4.3]: each frame gathers, at every real leaf, the
// diffuse cones over the previous frame's mipmap (gather.h), so L_{t+1} = direct +
// albedo x gather(L_t), from L_0 = `start` (the light a sequence carried, common/svo/propagate.h)
// or `direct`; with `clearEachFrame`, every frame gathers from `direct` alone (one bounce).
// Returns the last frame's radiance; `outputs` gets that frame's.
LeafRadiance propagateFrames(const Octree& octree, const Leaves& leaves, const LeafRadiance& direct,
                             const std::vector<shared::ConeData>& cones,
                             const shared::ConeTraceParams& params, int frames, bool clearEachFrame,
                             FirstStep first, FrameOutputs* outputs = nullptr,
                             const LeafRadiance* start = nullptr);

}  // namespace voxgi::cpu::svo
