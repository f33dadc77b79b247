// Shading from the octree on the CPU (docs/svo.md): per pixel, trace_cones' direct light with a
// shadow cone per light and the specular cone, read through the tree (no diffuse cones), plus the
// leaves' gathered light sampled trilinearly (shaders/shared/svo/shade_kernel.h), composed as the
// dense technique composes (compose_kernel.h).
#pragma once

#include <vector>

#include "common/buffer.h"
#include "cpu/svo/leaf_light.h"
#include "shaders/shared/vct/cone_types.h"

namespace voxgi::cpu::svo {

// The terms the composition needs per pixel.
struct PixelShading {
  std::vector<shared::PixelLight> light;
  std::vector<glm::vec3> color;
};

// Shades the gbuffer's pixels (common/shared_stages.inc's gbuffer buffers in `gbuffer`) from the
// tree's last frame: its leaf radiance (pyramid level 0), mipmap and gathered-light bricks, with
// `params` from treeConeTrace (common/svo/stage_inputs.h: no diffuse cones); the gathered light
// sampled with a cubic B-spline when `tricubic` (shade_kernel.h).
PixelShading shadePixels(const BufferSet& gbuffer, const Octree& octree, const Leaves& leaves,
                         const LeafRadiance& radiance, const NodeLevels& mips,
                         const Words& gatheredBricks, const std::vector<shared::LightData>& lights,
                         const std::vector<shared::ObjectData>& objects,
                         const shared::ConeTraceParams& params, glm::vec3 background,
                         bool tricubic);

}  // namespace voxgi::cpu::svo
