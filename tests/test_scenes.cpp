#include "tests/test_scenes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "common/fnv1a.h"
#include "common/pipeline.h"
#include "common/scene_io/scene_load.h"
#include "common/surface_sampling.h"
#include "common/voxel_triangles.h"
#include "cpu/backend.h"

namespace voxgi::test {

Scene makeScene(const std::vector<Triangle>& triangles, const GridSpec& grid,
                const Material& material) {
  Scene scene;
  scene.file = "test scene";
  scene.materials.push_back(material);
  Mesh mesh;
  mesh.name = "test mesh";
  for (const Triangle& t : triangles) {
    const auto base = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), t.begin(), t.end());
    mesh.triangles.emplace_back(base, base + 1, base + 2);
  }
  scene.meshes.push_back(mesh);
  scene.grid = grid;
  return scene;
}

std::vector<Triangle> quad(int axis, double at, glm::dvec2 lo, glm::dvec2 hi) {
  auto point = [&](double u, double v) {
    glm::dvec3 p;
    p[axis] = at;
    p[(axis + 1) % 3] = u;
    p[(axis + 2) % 3] = v;
    return p;
  };
  return {{point(lo.x, lo.y), point(hi.x, lo.y), point(hi.x, hi.y)},
          {point(lo.x, lo.y), point(hi.x, hi.y), point(lo.x, hi.y)}};
}

GridSpec unitGrid(int n, double size) {
  GridSpec g;
  g.min = glm::dvec3(0.0);
  g.size = size;
  g.resolution = n;
  return g;
}

Scene withCamera(Scene scene, glm::dvec3 position, glm::dvec3 lookAt, glm::dvec3 up, double fov,
                 int size) {
  scene.camera.position = position;
  scene.camera.lookAt = lookAt;
  scene.camera.up = up;
  scene.camera.fovYDeg = fov;
  scene.camera.width = scene.camera.height = size;
  return scene;
}

double polygonFormFactor(const std::vector<glm::dvec3>& v, glm::dvec3 p, glm::dvec3 n) {
  double sum = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 a = glm::normalize(v[i] - p), b = glm::normalize(v[(i + 1) % v.size()] - p);
    const glm::dvec3 c = glm::cross(a, b);
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(c));
  }
  return std::abs(sum) / (2.0 * std::numbers::pi);
}

Scene closedBox(int n, const Material& walls) {
  std::vector<Triangle> tris;
  const double lo = 2.5 / n, hi = (n - 2.5) / n;
  for (int axis = 0; axis < 3; ++axis) {
    for (const Triangle& t : quad(axis, lo, {lo, lo}, {hi, hi})) tris.push_back(t);
    for (Triangle t : quad(axis, hi, {lo, lo}, {hi, hi})) {
      std::swap(t[1], t[2]);  // facing -axis, into the box
      tris.push_back(t);
    }
  }
  return makeScene(tris, unitGrid(n), walls);
}

void expectFurnaceBounces(const float (&l)[4], float rho, float emission) {
  const float share = (l[1] - l[0]) / emission;
  EXPECT_LE(share, rho * 1.001f);
  for (int n = 1; n < 3; ++n) {
    const float before = l[n] - l[n - 1], bounce = l[n + 1] - l[n];
    EXPECT_LE(bounce, rho * before * 1.001f) << "bounce " << n + 1;
    EXPECT_GE(bounce, 0.9f * share * before) << "bounce " << n + 1;
  }
  EXPECT_LT(l[3], emission / (1.0f - rho));
}

double squareFormFactor(double s, double h) {
  const double a = s / h, ra = std::sqrt(1.0 + a * a);
  return 4.0 * (2.0 * a / ra * std::atan(a / ra)) / (2.0 * std::numbers::pi);
}

glm::dvec3 meanOf(const Image& image) {
  glm::dvec3 sum(0.0);
  for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
  return sum / double(image.pixels.size());
}

Light testLight() {
  Light sun;
  sun.type = Light::Type::directional;
  sun.direction = {0.0, -1.0, 0.0};
  sun.intensity = glm::vec3(1.0f);
  return sun;
}

Scene litQuad() {
  Scene scene = makeScene(quad(2, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  scene.lights.push_back(testLight());
  return scene;
}

BufferSet runCpu(const Scene& scene, VoxelizeMode mode) {
  Settings settings;
  settings.voxelizeMode = mode;
  settings.inspect = true;  // keeps the sums, as voxgi diff and dump do (Effect::voxel_sums)
  // Most test scenes have no light, which the planner answers with a black image and no
  // voxelization (EffectPlan::dark); voxelize does not read lights, so one is added here.
  Scene lit = scene;
  if (lit.unlit()) lit.lights.push_back(testLight());
  const VoxelTriangles tris = prepareVoxelTriangles(lit, lit.grid);
  BufferSet out;
  cpu::CpuBackend cpu;
  runPipeline(cpu, StageContext{vct(), lit, settings, tris}, out,
              &stageSpec(StageId::common_voxelize));
  return out;
}

BufferSet runCpuUntil(const Scene& scene, const Settings& settings, std::string_view last) {
  return runCpuUntil(vct(), scene, settings, last);
}

BufferSet runCpuUntil(const Technique& technique, const Scene& scene, const Settings& settings,
                      std::string_view last) {
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  BufferSet out;
  cpu::CpuBackend cpu;
  runPipeline(cpu, StageContext{technique, scene, settings, tris}, out,
              &resolveStage(technique, std::string(last)));
  return out;
}

const Technique& vct() {
  return findTechnique("vct");
}

Scene cornellBoxCloud(size_t points, bool glossy) {
  return sampledCloudScene(sourcePath("scenes/cornell_box.json"), points, glossy);
}

Scene sampledCloudScene(const std::string& file, size_t points, bool glossy) {
  Scene scene = loadScene(file);
  SurfaceSampling sampling;
  sampling.points = points;
  sampling.noise = 0.1;
  sampling.gradientAxis = 1;
  sampling.gradientRatio = 0.5;
  PointCloud cloud = sampleSurfaces(scene, sampling);
  cloud.name = "the sampled " + scene.file;
  Material m;
  m.name = "cloud";
  if (glossy) {
    m.specular = glm::vec3(0.3f);
    m.shininess = 40.0f;
  }
  cloud.material = uint32_t(scene.materials.size());
  scene.materials.push_back(m);
  std::erase_if(scene.meshes,
                [&](const Mesh& mesh) { return !scene.materials[mesh.material].emissive(); });
  scene.pointClouds.push_back(std::move(cloud));
  return scene;
}

testing::AssertionResult sameWords(const BufferSet& a, BufferId ia, const BufferSet& b,
                                   BufferId ib) {
  const Buffer &x = a.at(ia), &y = b.at(ib);
  if (x.words == y.words)
    return testing::AssertionSuccess()
           << x.spec->qualifiedName() << " = " << y.spec->qualifiedName();
  return testing::AssertionFailure()
         << x.spec->qualifiedName() << " differs from " << y.spec->qualifiedName();
}

glm::vec4 voxelValue(const Buffer& b, glm::ivec3 v) {
  const int n = b.extent.x;
  const size_t e = size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z));
  glm::vec4 r(0.0f);
  for (int c = 0; c < b.components(); ++c) r[c] = b.get<float>(e, c);
  return r;
}

uint64_t hashBuffers(const BufferSet& buffers) {
  uint64_t h = kFnv1aBasis;
  for (const auto& [id, b] : buffers) {
    const std::string name = bufferSpec(id).qualifiedName();
    h = fnv1a(b.words.data(), b.words.size() * sizeof(uint32_t),
              fnv1a(name.data(), name.size(), h));
  }
  return h;
}

std::string testTempDir() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir =
      testing::TempDir() + "voxgi_" + info->test_suite_name() + "." + info->name() + "/";
  // Emptied the first time a test asks, so nothing is left from an earlier run of it.
  static std::string emptied;
  if (emptied != dir) {
    std::filesystem::remove_all(dir);
    emptied = dir;
  }
  std::filesystem::create_directories(dir);
  return dir;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = testTempDir() + name;
  std::ofstream(path) << text;
  return path;
}

std::string sourcePath(const std::string& relative) {
  return std::string(VOXGI_SOURCE_DIR) + "/" + relative;
}

bool planItemIn(const EffectPlan& plan, const std::string& name) {
  for (const PlanItem& item : plan.items)
    if (item.name.find(name) != std::string::npos) return item.in;
  ADD_FAILURE() << "no plan item " << name;
  return false;
}

}  // namespace voxgi::test
