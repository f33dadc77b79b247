// The svo technique's scene samples (docs/svo.md, "Samples"): every point of the scene's point
// clouds and points spread over its meshes, in leaf voxel units with their regions of influence,
// prepared once on the host for both backends with the fixed-point and emission scales the build
// uses.
#pragma once

#include <cstdint>
#include <vector>

#include "common/scene.h"
#include "common/settings.h"
#include "shaders/shared/svo/build_kernel.h"

namespace voxgi::svo {

struct SampleSet {
  std::vector<shared::SvoSample> samples;
  // Units of a leaf sum per unit of opacity x cell volume: the largest power of two (at most 2^24)
  // for which no leaf's sum can pass 2^31 - 1 (the bound counts the samples near each block of
  // 8^3 leaves).
  float weightScale = 1.0f;
  float emissionScale = 1.0f;  // sample emission x this = emission; a power of two >= the largest
  size_t cloudPoints = 0, meshPoints = 0;
};

// Samples of the scene over the grid cube at 2^depth leaves per side. Meshes get `meshDensity`
// points per leaf face of area (build.mesh_density), per material, from `seed`. A point's RoI edge
// is the side of a square of its area (pi r^2 / 2, common/scene_io/point_neighbours.h), in leaves,
// at most 1; its opacity density is the reciprocal, so a surface's samples add opacity 1 per leaf
// face. Under emitters.mode=area_lights the meshes' emissive triangles are area lights, so the
// points sampled on them carry no emission; a point cloud's emission stays. Throws InputError
// naming build.mesh_density when the samples would not fit in memory.
SampleSet prepareSamples(const Scene& scene, int depth, double meshDensity, uint64_t seed,
                         EmitterLighting emitters);

}  // namespace voxgi::svo
