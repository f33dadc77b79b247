// svo's propagate on the GPU (shaders/svo/propagate_inject.comp, propagate_gather.comp): the twin
// of cpu/svo/propagate.h, shaped alike (injectLeaves, bounceOnce, propagateFrames), running the
// cone library's kernels on an octree in the canonical form. On llvmpipe injection equals the
// CPU's bit for bit; the gather differs by an ULP here and there (GLSL's division normalising the
// leaf normal), as the dense bounce does.
#pragma once

#include <vector>

#include "gpu/svo/svo_volumes.h"
#include "shaders/shared/cone/cone_types.h"
#include "shaders/shared/cone/voxel_light.h"

namespace voxgi::gpu::svo {

voxgi::svo::LeafRadiance injectLeaves(GlContext& context, const Tree& tree,
                                      const voxgi::svo::Leaves& leaves,
                                      const std::vector<shared::LightData>& lights,
                                      const shared::LightVoxelsParams& params);

voxgi::svo::LeafRadiance bounceOnce(
    GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
    const voxgi::svo::LeafRadiance& direct, const voxgi::svo::LeafRadiance& source,
    const std::vector<shared::ConeData>& cones, const shared::ConeTraceParams& params,
    voxgi::svo::FirstStep first, voxgi::svo::FrameOutputs* outputs = nullptr);

// `frames` progressive bounces, as cpu/svo/propagate.h's propagateFrames: from `start` (the light
// a sequence carried) or `direct`; with `clearEachFrame`, every frame gathers from `direct` alone.
voxgi::svo::LeafRadiance propagateFrames(GlContext& context, const Tree& tree,
                                         const voxgi::svo::Leaves& leaves,
                                         const voxgi::svo::LeafRadiance& direct,
                                         const std::vector<shared::ConeData>& cones,
                                         const shared::ConeTraceParams& params, int frames,
                                         bool clearEachFrame, voxgi::svo::FirstStep first,
                                         voxgi::svo::FrameOutputs* outputs = nullptr,
                                         const voxgi::svo::LeafRadiance* start = nullptr);

}  // namespace voxgi::gpu::svo
