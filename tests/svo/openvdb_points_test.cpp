// An independent check of the octree's leaf level (docs/svo.md): OpenVDB's own point rasterisation
// (openvdb::points::rasterizeTrilinear) of the same points at the same voxel size must give the
// leaves' resolved colours. With a one-leaf RoI (the edge clamps to 1, density 1) a sample's box
// overlaps each leaf by the tent weight of its distance to the leaf's centre, which is
// rasterizeTrilinear's weight, and OpenVDB normalises by the weight sum as resolving the leaves
// does (albedo sum / opacity sum). Only the fixed-point rounding of the sums differs.
#include <gtest/gtest.h>

#include <atomic>
#include <random>

#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointRasterizeTrilinear.h>

#include "common/svo/samples.h"
#include "common/svo/stage_inputs.h"
#include "cpu/svo/svo_volumes.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

TEST(SvoOpenVdb, LeafColoursEqualOpenVdbPointRasterisation) {
  constexpr int kDepth = 5;
  const int n = 1 << kDepth;
  Scene scene;
  scene.file = "test scene";
  scene.grid = unitGrid(n, 2.0);
  scene.grid.min = glm::dvec3(-1.0, 0.5, 3.0);  // away from the origin: the transform must line up
  scene.materials.push_back(Material{});
  const double leaf = scene.grid.voxelSize();
  PointCloud cloud;
  cloud.name = "random points";
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    cloud.positions.push_back(scene.grid.min + glm::dvec3(u(rng), u(rng), u(rng)) * 2.0);
    cloud.normals.emplace_back(0.0f, 1.0f, 0.0f);
    cloud.radii.push_back(float(leaf));  // edge sqrt(pi/2) r / leaf > 1: clamped to one leaf
    cloud.colors.emplace_back(float(u(rng)), float(u(rng)), float(u(rng)));
  }
  scene.pointClouds.push_back(cloud);

  const svo::SampleSet set = svo::prepareSamples(scene, kDepth, 4.0, 1, EmitterLighting::voxels);
  ASSERT_EQ(set.samples.size(), cloud.size());
  for (const auto& s : set.samples) ASSERT_EQ(s.edge, 1.0f);
  const cpu::svo::Octree o = cpu::svo::buildOctree(set.samples, kDepth);
  const Words sums = cpu::svo::accumulateLeaves(o, set.samples, set.weightScale, scene.file);
  const svo::Leaves leaves = svo::resolveLeaves(sums, set.weightScale, set.emissionScale);

  openvdb::initialize();
  std::vector<openvdb::Vec3R> positions;
  std::vector<openvdb::Vec3f> colors;
  for (size_t i = 0; i < cloud.size(); ++i) {
    const glm::dvec3 p = cloud.positions[i];
    positions.emplace_back(p.x, p.y, p.z);
    colors.emplace_back(cloud.colors[i].x, cloud.colors[i].y, cloud.colors[i].z);
  }
  // Voxel (i, j, k) centred at grid.min + (i + 1/2) leaf, as the leaves and voxgi's dumps.
  auto transform = openvdb::math::Transform::createLinearTransform(leaf);
  transform->postTranslate(openvdb::Vec3d(
      scene.grid.min.x + 0.5 * leaf, scene.grid.min.y + 0.5 * leaf, scene.grid.min.z + 0.5 * leaf));
  const openvdb::points::PointAttributeVector<openvdb::Vec3R> wrapper(positions);
  const auto index =
      openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(wrapper, *transform);
  auto grid = openvdb::points::createPointDataGrid<openvdb::points::NullCodec,
                                                   openvdb::points::PointDataGrid>(*index, wrapper,
                                                                                   *transform);
  openvdb::points::appendAttribute<openvdb::Vec3f>(grid->tree(), "Cd");
  const openvdb::points::PointAttributeVector<openvdb::Vec3f> cd(colors);
  openvdb::points::populateAttribute<openvdb::points::PointDataTree, openvdb::tools::PointIndexTree,
                                     openvdb::points::PointAttributeVector<openvdb::Vec3f>>(
      grid->tree(), index->tree(), "Cd", cd);
  const auto raster =
      openvdb::points::rasterizeTrilinear<false, openvdb::Vec3f>(grid->tree(), "Cd");

  // A leaf sum is off by at most half a unit (1 / weightScale) per sample that touches it (its
  // centre within a leaf of the leaf's centre on every axis); the colour divides such sums by the
  // weight: |error| <= (touching / 2 / scale) (1 + colour) / weight.
  std::vector<int> touching(size_t(n) * size_t(n) * size_t(n), 0);
  for (const auto& s : set.samples) {
    const glm::ivec3 base(glm::floor(glm::vec3(s.position) - 0.5f));
    for (int k = 0; k < 8; ++k) {
      const glm::ivec3 c = base + glm::ivec3(k & 1, (k >> 1) & 1, k >> 2);
      if (glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) &&
          glm::all(glm::lessThan(c, glm::ivec3(n))))
        ++touching[size_t(c.x) + size_t(n) * (size_t(c.y) + size_t(n) * size_t(c.z))];
    }
  }
  std::atomic<size_t> compared = 0;
  cpu::svo::forEachRealLeaf(o, [&](size_t slot, glm::ivec3 v) {
    const glm::vec4 a = leaves.albedo[slot];
    if (a.a < 1e-3f) return;  // a weight this small leaves the rounding bound meaningless
    const openvdb::Vec3f expected = raster->getValue(openvdb::Coord(v.x, v.y, v.z));
    const int t = touching[size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z))];
    const double rounding = 2.0 * t * 0.5 / double(set.weightScale) / double(a.a);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(a[c] / a.a, expected[c], rounding + 1e-5)
          << "leaf " << v.x << " " << v.y << " " << v.z;
    ++compared;
  });
  EXPECT_GT(compared, size_t(n * n * n / 2));
}

}  // namespace
}  // namespace voxgi::test
