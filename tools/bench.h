// Benchmarks (docs/benchmarks.md), wall-clock medians measured side by side in one run:
// `voxgi bench voxelize` against OpenVDB's tools::meshToVolume on the same mesh and voxel size;
// `voxgi bench vct` per-stage times of the VCT pipeline, plus mip against a memcpy of its input;
// `voxgi bench lpv` per-stage times of lpv and holpv, propagation against the bytes it moves;
// `voxgi bench svo` the octree's build from a point cloud against OpenVDB's point rasterisation;
// `voxgi bench path` the path tracer's efficiency per estimator against the former one;
// `voxgi bench frames` a sequence's per-frame cost, each frame updated against rebuilt.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/pipeline.h"

namespace voxgi::tools {

struct BenchOptions {
  std::vector<int> resolutions{128, 256, 512};
  std::string bunny = "scenes/bunny.obj";
  int generatedTriangles = 1000000;  // 0: skip the generated mesh
  int repeats = 3;
  bool gpu = true;
  std::string gl = "osmesa";  // the GPU column's GL platform (--gl)
  std::string json;
};

void addBenchOptions(CLI::App& cmd, BenchOptions& options);
// --no-gpu and --gl, the GPU column of every benchmark: OSMesa (llvmpipe) by default, EGL for a
// hardware GPU.
void addGpuColumnOptions(CLI::App& cmd, bool& gpu, std::string& gl);
int runBenchVoxelize(const BenchOptions& options);

struct BenchVctOptions {
  std::vector<std::string> scenes{"scenes/cornell_box.json", "scenes/bunny.json"};
  std::vector<int> resolutions{64, 128, 256};
  std::vector<int> images{256, 512};
  std::vector<int> threads{1, 2};
  int mipResolution = 256;  // 0: skip the mip-vs-memcpy line
  int repeats = 3;
  bool gpu = true;
  std::string gl = "osmesa";  // the GPU column's GL platform (--gl)
  std::string preset = "default";
  std::vector<std::string> sets;
  std::string json;
};

void addBenchVctOptions(CLI::App& cmd, BenchVctOptions& options);
int runBenchVct(const BenchVctOptions& options);

struct BenchLpvOptions {
  std::vector<std::string> scenes{"scenes/cornell_box_lpv.json"};
  std::vector<int> resolutions{32, 64};
  std::vector<int> steps{8, 16};
  std::vector<int> threads{1, 2};
  int repeats = 3;
  bool gpu = true;
  std::string gl = "osmesa";  // the GPU column's GL platform (--gl)
  std::string json;
};

void addBenchLpvOptions(CLI::App& cmd, BenchLpvOptions& options);
int runBenchLpv(const BenchLpvOptions& options);

struct BenchSvoOptions {
  std::string cloud;         // empty: generate one from the Cornell box
  int64_t points = 1400000;  // [Salm 2015]'s CaveCloud
  std::vector<int> depths{7, 8};
  std::vector<int> threads{1, 2};
  std::vector<int> stageDepths{6, 7};  // the technique's stages through the runner
  bool gpu = true;
  std::string gl = "osmesa";  // the GPU column's GL platform (--gl)
  int repeats = 3;
  std::string json;
};

void addBenchSvoOptions(CLI::App& cmd, BenchSvoOptions& options);
int runBenchSvo(const BenchSvoOptions& options);

struct BenchPathOptions {
  std::vector<std::string> scenes{"scenes/cornell_box.json", "scenes/bunny.json"};
  int image = 128;
  int spp = 64;
  int referenceSpp = 4096;
  int threads = 0;  // 0: all cores
  int repeats = 3;
  std::string json;
};

void addBenchPathOptions(CLI::App& cmd, BenchPathOptions& options);
int runBenchPath(const BenchPathOptions& options);

struct BenchFramesOptions {
  std::vector<std::string> scenes{"scenes/bunny_crowd.json"};
  std::vector<std::string> techniques{"vct", "lpv", "svo"};
  std::string frames = "0:48:4";
  std::vector<int> resolutions{64, 128};
  std::vector<int> threads{1, 2};
  int repeats = 3;
  bool gpu = true;
  std::string gl = "osmesa";      // the GPU column's GL platform (--gl)
  std::vector<std::string> sets;  // key=value for every technique (a key it lacks: refused)
  std::string json;
};

void addBenchFramesOptions(CLI::App& cmd, BenchFramesOptions& options);
int runBenchFrames(const BenchFramesOptions& options);

// The median time of each stage the plan runs after voxelize on `backend`, each from the CPU's
// outputs of the stages before it (voxelize has its own benchmark); stage -> seconds.
std::vector<std::pair<std::string, double>> timeStages(const StageContext& ctx, int repeats,
                                                       StageBackend& backend);

// The median of `values` (the upper one of the middle two for an even count).
double median(std::vector<double> values);

// The median wall-clock time of `repeats` runs of `run`.
double medianSeconds(int repeats, const std::function<void()>& run);
// The wall-clock time of one run of `run`.
double elapsedSeconds(const std::function<void()>& run);

}  // namespace voxgi::tools
