// voxgi sample: a scene's meshes as a point-cloud PLY (common/surface_sampling.h), with a
// scanner's noise and uneven density.
#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>

#include "common/error.h"
#include "common/memory.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/scene_io/point_cloud_ply.h"
#include "common/surface_sampling.h"
#include "tools/command.h"

namespace voxgi::tools {
namespace {

struct SampleOptions {
  std::string scene, out, gradient;
  int64_t points = 0;
  double noise = 0.0;
  uint64_t seed = 1;
};

// --density-gradient "y:0.25" into the sampling's axis and ratio.
void readGradient(const std::string& gradient, SurfaceSampling& sampling) {
  const size_t colon = gradient.find(':');
  const std::string axis = gradient.substr(0, colon);
  double ratio = 0.0;
  const std::string value = colon == std::string::npos ? "" : gradient.substr(colon + 1);
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), ratio);
  if (axis.size() != 1 || axis.find_first_of("xyz") != 0 || ec != std::errc() ||
      end != value.data() + value.size() || !(ratio > 0.0 && ratio <= 1e6))
    throw InputError(
        "--density-gradient", "",
        "expected AXIS:RATIO with AXIS x, y or z and RATIO in (0, 1e6], got '" + gradient + "'");
  sampling.gradientAxis = axis[0] - 'x';
  sampling.gradientRatio = ratio;
}

int runSample(const SampleOptions& o) {
  checkOutputPath(o.out);
  SurfaceSampling sampling;
  sampling.points = size_t(o.points);
  sampling.noise = o.noise;
  sampling.seed = o.seed;
  if (!o.gradient.empty()) readGradient(o.gradient, sampling);
  // Positions, normals, colours and radii in memory (52 bytes) and the file (52 bytes).
  requireMemory(uint64_t(o.points) * 104u, "the sampled points", "--points", "");
  const Scene scene = loadScene(o.scene);
  const auto start = std::chrono::steady_clock::now();
  const PointCloud cloud = sampleSurfaces(scene, sampling);
  writePointCloudPly(cloud, o.out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "sampled " << cloud.size() << " points from " << scene.triangleCount()
            << " triangles in " << seconds << " s -> " << o.out << "\n";
  return kExitOk;
}

}  // namespace

void addSampleCommand(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<SampleOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sample", "a scene's meshes as a point-cloud PLY, with a scanner's noise and uneven density");
  cmd->add_option("scene", o->scene, "scene file or mesh file")->required();
  cmd->add_option("--points", o->points, "number of points")
      ->required()
      ->check(CLI::Range(int64_t(1), int64_t(1) << 32));
  cmd->add_option("--noise", o->noise,
                  "standard deviation of an offset along the normal, scene units")
      ->check(CLI::Range(0.0, 1e15));
  cmd->add_option("--density-gradient", o->gradient,
                  "AXIS:RATIO, the density along x, y or z from 1 to RATIO (y:0.25)");
  cmd->add_option("--seed", o->seed, "random seed");
  cmd->add_option("--out", o->out, "output .ply")->required();
  commands.push_back({cmd, [o] { return runSample(*o); }});
}

}  // namespace voxgi::tools
