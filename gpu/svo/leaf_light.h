// Light in the sparse voxel octree on the GPU (shaders/svo/propagate_inject.comp, mip.comp,
// propagate_gather.comp): the twins of cpu/svo/leaf_light.h, running the same shared kernels on an
// octree in the canonical form. On llvmpipe injection and the mipmap equal the CPU's bit for bit;
// the gather differs by an ULP here and there (GLSL's division normalising the leaf normal), as
// the dense bounce does.
#pragma once

#include <vector>

#include "common/svo/canonical.h"
#include "common/svo/light_types.h"
#include "gpu/context.h"
#include "shaders/shared/vct/cone_types.h"
#include "shaders/shared/vct/light_voxels_kernel.h"

namespace voxgi::gpu::svo {

// The octree's words the light passes read (nodes, tile records, leaf tiles) at tree `depth`.
struct Tree {
  const voxgi::svo::OctreeWords& words;
  int depth;
};

// A new buffer of the bricks of `tileCount` tiles (shaders/svo/mip_brick.comp): 27 texels of
// `faces` RGBA values each, from `interior`'s `faces` values per voxel (8 a tile), the tiles'
// records in `tileRecords` (leaf tiles, or the node tiles) and their neighbours through `nodes`.
GLuint buildBricks(const Gl& gl, GLuint nodes, GLuint tileRecords, GLuint interior,
                   size_t tileCount, int faces);

voxgi::svo::LeafRadiance injectLeaves(GlContext& context, const Tree& tree,
                                      const voxgi::svo::Leaves& leaves,
                                      const std::vector<shared::LightData>& lights,
                                      const shared::LightVoxelsParams& params);

voxgi::svo::NodeLevels mipTree(GlContext& context, const Tree& tree,
                               const voxgi::svo::Leaves& leaves,
                               const voxgi::svo::LeafRadiance& radiance,
                               voxgi::svo::FirstStep first);

voxgi::svo::LeafRadiance bounceOnce(
    GlContext& context, const Tree& tree, const voxgi::svo::Leaves& leaves,
    const voxgi::svo::LeafRadiance& direct, const voxgi::svo::LeafRadiance& source,
    const std::vector<shared::ConeData>& cones, const shared::ConeTraceParams& params,
    voxgi::svo::FirstStep first, voxgi::svo::FrameOutputs* outputs = nullptr);

}  // namespace voxgi::gpu::svo
