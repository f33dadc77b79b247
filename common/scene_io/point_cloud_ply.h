// Point clouds from PLY files (docs/svo.md, "Point clouds"): one `vertex` element of scalar
// properties, ASCII or binary in either byte order. Assimp reads such files too, but it drops
// per-point properties it does not know (the radius) and took 485 ms for 1.4 M binary points on
// top of the 356 ms of the check voxgi runs before any Assimp import (common/scene_io/ply_check.h);
// this reader is that check's header parser and value decoding, reading the values in the same
// pass.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene.h"
#include "common/scene_io/ply_check.h"

namespace voxgi {

// What the file holds, in file order and file units.
struct PlyPoints {
  std::vector<glm::dvec3> positions;
  std::vector<glm::vec3> normals;  // nx ny nz, not normalised; empty when the file has none
  std::vector<glm::vec3> colors;   // red green blue in [0, 1] (integers / their maximum); or empty
  std::vector<float> radii;        // radius; or empty
};

// Whether a checked header describes a point cloud: a vertex element, and no other element with
// instances (exporters write "element face 0").
bool plyIsPointCloud(const PlyHeader& header);

// Reads a point-cloud PLY. Throws InputError naming the file, the element or vertex and the field
// for anything else: a header readPlyHeader refuses, a list property, a body whose size is not
// what the header declares (checked before any allocation), a non-finite position or normal, a
// zero normal, a float colour outside [0, 1], a radius that is not a positive finite number, or
// only some of nx/ny/nz or red/green/blue.
PlyPoints readPlyPoints(const std::string& path);

// The cloud as a binary little-endian PLY: x y z (double), nx ny nz, red green blue (float,
// sRGB-encoded as PLY colours are), radius (float). Written to a temporary file and renamed
// (common/io/output_file.h).
void writePointCloudPly(const PointCloud& cloud, const std::string& path);

}  // namespace voxgi
