// Scenes built in code for tests, and helpers to run and inspect the voxelize stage.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/buffer.h"
#include "common/io/image_io.h"
#include "common/scene.h"
#include "common/stage.h"

namespace voxgi::test {

using Triangle = std::array<glm::dvec3, 3>;

// One mesh of the given triangles with one material, on the given grid.
Scene makeScene(const std::vector<Triangle>& triangles, const GridSpec& grid,
                const Material& material = Material{});
// Two triangles covering the axis-aligned rectangle [lo, hi] in the plane axis = `at`.
std::vector<Triangle> quad(int axis, double at, glm::dvec2 lo, glm::dvec2 hi);
// A unit grid [0, size]^3 with N^3 voxels.
GridSpec unitGrid(int n, double size = 1.0);
// A closed box in the unit grid of n voxels: six inward-facing walls through the centres of voxels
// 2 and n - 3 on each axis, all of one material (emitting in the radiosity tests that use it).
Scene closedBox(int n, const Material& walls);
// The furnace (a closed box whose walls all emit E with albedo rho): its floor's radiance L_0 ..
// L_3 after 0 .. 3 bounces, each bounce b_n = L_n - L_(n-1) at most rho times the one before
// (energy) and at least 0.9 of the first bounce's share b_1 / E times it: every wall sends out the
// same radiance after every bounce, so the cones gather the same fraction of it each time (10 % for
// the corners and edges, whose radiance lags the walls' middles). Measured: b_(n+1) / b_n over
// b_1 / E is 0.98 (directional pyramid), 0.99 (octree), 1.19 and 1.42 (isotropic pyramid).
void expectFurnaceBounces(const float (&l)[4], float rho, float emission);

// `scene` seen from `position` toward `lookAt` through a square image of `size` pixels.
Scene withCamera(Scene scene, glm::dvec3 position, glm::dvec3 lookAt, glm::dvec3 up, double fov,
                 int size);
// The mean pixel of an image, per channel.
glm::dvec3 meanOf(const Image& image);

// Lambert's formula: the form factor from a point with unit normal n to the convex polygon v
// (seen from its front, wholly above the point's plane), in double precision.
double polygonFormFactor(const std::vector<glm::dvec3>& v, glm::dvec3 p, glm::dvec3 n);
// The form factor from a point to a parallel square of half-size s centred at distance h above it,
// facing it: four corner rectangles of Howell's catalogue (configuration B-3).
double squareFormFactor(double s, double h);

// A directional light of irradiance 1 straight down: what a test scene gets where a stage under
// test runs only in a lit scene (EffectPlan::dark).
Light testLight();
// The quad z = 0.3 over [0.1, 0.9]^2 in the unit grid of 16 voxels, lit by testLight: a scene in
// which every stage of vct runs.
Scene litQuad();
// The voxelize stage on the CPU (the scene lit by testLight if nothing lights it), its fixed-point
// sums kept (Settings::inspect).
BufferSet runCpu(const Scene& scene, VoxelizeMode mode);
// Runs the CPU stages the technique's plan runs (vct's by default), in graph order, up to and
// including `last` ("mip", "vct/mip").
BufferSet runCpuUntil(const Scene& scene, const Settings& settings, std::string_view last);
BufferSet runCpuUntil(const Technique& technique, const Scene& scene, const Settings& settings,
                      std::string_view last);
// The voxel cone tracing technique.
const Technique& vct();
// Whether the plan item whose name contains `name` is in; a test failure when there is none.
bool planItemIn(const EffectPlan& plan, const std::string& name);
// The Cornell box with its walls and blocks as `points` sampled points (noise 0.1 along the normal,
// half as dense at the top, as the shipped cornell_box_cloud.json's), its light a mesh; the cloud
// carries the walls' colours and a glossy material of its own when `glossy`.
Scene cornellBoxCloud(size_t points, bool glossy = false);
// The scene file's non-emitting meshes replaced by `points` points sampled from them, as
// cornellBoxCloud's.
Scene sampledCloudScene(const std::string& file, size_t points, bool glossy);
// Voxel v's components of a volume buffer.
glm::vec4 voxelValue(const Buffer& b, glm::ivec3 v);
// Whether buffer `ia` of `a` and buffer `ib` of `b` hold the same words (naming both when not).
testing::AssertionResult sameWords(const BufferSet& a, BufferId ia, const BufferSet& b,
                                   BufferId ib);
inline testing::AssertionResult sameWords(const BufferSet& a, const BufferSet& b, BufferId id) {
  return sameWords(a, id, b, id);
}
// FNV-1a over every buffer's qualified name and words.
uint64_t hashBuffers(const BufferSet& buffers);
std::string sourcePath(const std::string& relative);  // relative to the project root
// A folder of the running test's own (ctest runs tests as parallel processes), emptied when first
// asked for in a run, ending in '/'.
std::string testTempDir();
// Each component of `got` within `tolerance` of `want`'s.
inline void expectVec(const glm::dvec3& got, const glm::dvec3& want, double tolerance = 1e-9) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "component " << c;
}
// Writes `text` to `name` in testTempDir(); returns its path.
std::string writeTemp(const std::string& name, const std::string& text);

}  // namespace voxgi::test
