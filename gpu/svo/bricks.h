// Every tile of a tree level as a brick on the GPU (shaders/svo/bricks.comp), the twin of
// cpu/svo/bricks.h: svo's propagate lays out the gathered light and every frame's source with
// it, and svo's shade the light its cones read.
#pragma once

#include <cstddef>

#include "gpu/gl.h"

namespace voxgi::gpu::svo {

// A new buffer of the bricks of `tileCount` tiles: 27 texels of `faces` RGBA values each, from
// `interior`'s `faces` values per voxel (8 a tile), the tiles' records in `tileRecords` (leaf
// tiles, or the node tiles) and their neighbours through `nodes`.
GLuint completeBricks(const Gl& gl, GLuint nodes, GLuint tileRecords, GLuint interior,
                      size_t tileCount, int faces);

}  // namespace voxgi::gpu::svo
