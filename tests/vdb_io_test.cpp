#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "common/io/vdb_io.h"
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

// A series buffer of SH volumes: one RGB grid per step and coefficient, named
// <buffer>.step_<k>_c<i>, holding (r_i, g_i, b_i) of that step's cells.
TEST(VdbIo, ShSeriesBecomesOneRgbGridPerStepAndCoefficient) {
  const int n = 4, steps = 3;
  Buffer series(BufferId::lpv_propagate_steps_sh4, glm::ivec3(n, n, n * steps));
  for (int k = 0; k < steps; ++k)
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 4; ++i)
        series.set(size_t(k) * n * n * n + 5, c * 4 + i, float(100 * k + 10 * i + c + 1));
  const std::string path = testTempDir() + "series.vdb";
  writeVdb(path, {&series}, unitGrid(n));
  openvdb::io::File file(path);
  file.open();
  int grids = 0;
  for (auto it = file.beginName(); it != file.endName(); ++it) ++grids;
  EXPECT_EQ(grids, steps * 4);
  const glm::ivec3 cell(1, 1, 0);  // element 5 of a 4^3 volume
  for (int k = 0; k < steps; ++k)
    for (int i = 0; i < 4; ++i) {
      const auto g = openvdb::gridPtrCast<openvdb::Vec3SGrid>(
          file.readGrid("steps_sh4.step_" + std::to_string(k) + "_c" + std::to_string(i)));
      ASSERT_TRUE(g) << k << " " << i;
      const openvdb::Vec3s v =
          g->getConstAccessor().getValue(openvdb::Coord(cell.x, cell.y, cell.z));
      for (int c = 0; c < 3; ++c) EXPECT_EQ(v[c], float(100 * k + 10 * i + c + 1));
    }
}

}  // namespace
}  // namespace voxgi::test
