// `voxgi bench voxelize`: wall-clock medians of the voxelize stage, side by side in one run with
// OpenVDB's tools::meshToVolume on the same mesh and voxel size (docs/benchmarks.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace voxgi::tools {

struct BenchOptions {
  std::vector<int> resolutions{128, 256, 512};
  std::string bunny = "scenes/bunny.obj";
  int generatedTriangles = 1000000;  // 0: skip the generated mesh
  int repeats = 3;
  bool gpu = true;
  std::string json;
};

void addBenchOptions(CLI::App& cmd, BenchOptions& options);
int runBenchVoxelize(const BenchOptions& options);

}  // namespace voxgi::tools
