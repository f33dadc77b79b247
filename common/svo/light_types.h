// The values light in the sparse voxel octree works on, the same for both backends (docs/svo.md):
// per leaf (8 a leaf tile, in local-id order, 0 for a tile's empty leaves) and per node of the
// node levels.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace voxgi::svo {

// Values of the leaves, 8 a leaf tile in local-id order (0 for the empty leaves of a tile).
struct Leaves {
  std::vector<glm::vec4> albedo;    // rgb: sum of weight x albedo; a: opacity (may pass 1)
  std::vector<glm::vec3> normal;    // sum of weight x normal (the NDF, premultiplied)
  std::vector<glm::vec3> emission;  // sum of weight x emission, radiance units
};

// Where build's `leaves` buffer (common/svo/stages.inc) holds a leaf's values: ten halves a leaf.
constexpr int kLeafAlbedo = 0;    // 0..2: Leaves::albedo's rgb
constexpr int kLeafOpacity = 3;   // Leaves::albedo's a
constexpr int kLeafNormal = 4;    // 4..6
constexpr int kLeafEmission = 7;  // 7..9
constexpr int kLeafValues = 10;

// Outgoing radiance per leaf, premultiplied by the leaf's opacity clamped to 1 (a: that opacity),
// 8 a leaf tile; what pyramid level 0 holds.
using LeafRadiance = std::vector<glm::vec4>;

// The node levels' six faces (+x -x +y -y +z -z as cone travel directions, cone/mip.h): levels[l]
// for l = 1 .. depth-1 holds 8 nodes x 6 faces per node tile of the level, in tile order.
struct NodeLevels {
  std::vector<std::vector<glm::vec4>> levels;
};

// How the first step from the isotropic leaves weights a leaf per face: not at all (the dense
// mip's compositing), or by (1 - n.f)/2 of its mean normal n and the face's travel direction f
// ([Salm 2015, §4.4.2]; radiance leaving along -f).
enum class FirstStep { plain, ndf };

// What a frame leaves besides the radiance: the mipmap it gathered from, and per leaf the gathered
// E / pi premultiplied by the clamped opacity (a: that opacity), which shading interpolates, and
// straight (what propagate.carry carries to the next frame, common/svo/propagate.h).
struct FrameOutputs {
  NodeLevels pyramid;
  LeafRadiance gathered;
  std::vector<glm::vec3> gatheredStraight;
};

}  // namespace voxgi::svo
