// Meshes as point clouds (docs/svo.md, "Point clouds"): points spread over the triangles by area,
// as deterministic as everything else (point i is a hash of the seed and i), with the noise and
// uneven density a scanner gives. `voxgi sample` writes them as PLY; the svo technique samples
// the meshes of a scene this way.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "common/scene.h"

namespace voxgi {

struct SurfaceSampling {
  size_t points = 0;
  uint64_t seed = 1;
  double noise = 0.0;  // standard deviation of a Gaussian offset along the normal, world units
  // Density along `axis` (0, 1, 2; -1: uniform) from 1 at the scene's low end to `ratio` at its
  // high end, linearly: a scanner sees near surfaces densely and far ones sparsely.
  int gradientAxis = -1;
  double gradientRatio = 1.0;
  // Only the triangles of this material, emissive or not (-1: every non-emissive material).
  int material = -1;
};

// `sampling.points` points on the scene's meshes (every triangle with area, but for emissive
// ones unless `sampling.material` names one: a PLY carries no emission, so `voxgi sample` leaves
// emitters as meshes beside the cloud),
// each with the triangle's right-hand normal, its material's albedo (times its texture there) as
// colour and a radius with
// pi r^2 = twice the area per point (common/scene_io/point_neighbours.h's convention). Throws
// InputError naming the scene when it has no triangle with area to sample.
PointCloud sampleSurfaces(const Scene& scene, const SurfaceSampling& sampling);

// The area of the triangles sampleSurfaces would sample.
double sampledArea(const Scene& scene, int material);

}  // namespace voxgi
