#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "common/vdb_io.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

TEST(VdbIo, EveryVoxelizeBufferRoundTrips) {
  Material m;
  m.emission = glm::vec3(2.0f);
  Scene scene = makeScene(quad(2, 0.4, {0.1, 0.2}, {0.8, 0.9}), unitGrid(16), m);
  scene.grid.min = {-3.0, 1.5, 2.0};
  scene.grid.size = 2.0;
  for (auto& p : scene.meshes[0].positions) p = scene.grid.min + p * 2.0;
  const BufferSet b = runCpu(scene, VoxelizeMode::antialiased);
  std::vector<const Buffer*> all;
  for (const auto& [id, buffer] : b) all.push_back(&buffer);
  const std::string path = testTempDir() + "roundtrip.vdb";
  writeVdb(path, all, scene.grid);
  GridSpec read;
  std::vector<const BufferSpec*> specs;
  for (const Buffer* x : all) specs.push_back(x->spec);
  const BufferSet back = readVdb(path, read, specs);
  EXPECT_EQ(read.resolution, 16);
  EXPECT_EQ(read.min, scene.grid.min);
  EXPECT_EQ(read.size, scene.grid.size);
  ASSERT_EQ(back.size(), b.size());
  for (const auto& [id, buffer] : b)
    EXPECT_EQ(back.at(id).words, buffer.words) << buffer.spec->qualifiedName();
}

TEST(VdbIo, VoxelCentresLineUpWithTheWorld) {
  Scene scene = makeScene(quad(2, 0.4, {0.1, 0.2}, {0.8, 0.9}), unitGrid(8));
  scene.grid.min = {10.0, 20.0, 30.0};
  scene.grid.size = 4.0;  // h = 0.5
  const BufferSet b = runCpu(makeScene(quad(2, 0.4, {0.1, 0.2}, {0.8, 0.9}), unitGrid(8)),
                             VoxelizeMode::conservative);
  const std::string path = testTempDir() + "transform.vdb";
  writeVdb(path, {&b.at(BufferId::common_voxelize_opacity)}, scene.grid);
  openvdb::io::File file(path);
  file.open();
  const auto grid = file.readGrid("opacity");
  const openvdb::Vec3d centre = grid->indexToWorld(openvdb::Coord(1, 2, 3));
  EXPECT_DOUBLE_EQ(centre.x(), 10.0 + 1.5 * 0.5);
  EXPECT_DOUBLE_EQ(centre.y(), 20.0 + 2.5 * 0.5);
  EXPECT_DOUBLE_EQ(centre.z(), 30.0 + 3.5 * 0.5);
  EXPECT_EQ(grid->getGridClass(), openvdb::GRID_FOG_VOLUME);
}

}  // namespace
}  // namespace voxgi::test
