// What a point cloud's file may leave out, estimated from each point's nearest neighbours (a
// nanoflann k-d tree; docs/svo.md, "Point clouds"): disc radii from the local density and normals
// from the neighbours' covariance.
#pragma once

#include <glm/glm.hpp>

#include "common/scene.h"

namespace voxgi {

// Neighbours each estimate uses: the point itself and its 15 nearest.
constexpr int kNeighbours = 16;

// Fills the radii of points whose file had none: r = sqrt(2 / 8) d8, with d8 the distance to the
// 8th nearest other point, so that the disc's area pi r^2 is twice the area per point the local
// density gives (pi d8^2 / 8) and neighbouring discs overlap. A point with 8 others at its position
// takes the median of the others' radii. Throws InputError naming the cloud when every point
// coincides with 8 others, or the cloud has fewer than 9 points.
void estimateRadii(PointCloud& cloud);

// Fills the normals: the eigenvector of the smallest eigenvalue of the covariance of the point and
// its 15 nearest neighbours, turned toward `viewpoint` (as a scanner sees the surface).
void estimateNormals(PointCloud& cloud, const glm::dvec3& viewpoint);

}  // namespace voxgi
