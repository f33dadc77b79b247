// `voxgi bench lpv`: the median time of every stage after voxelize of lpv and holpv, per scene,
// grid resolution, step count, occlusion and thread count on the CPU and on the GPU backend
// (OSMesa); the HOLPV / LPV ratio of propagate; and propagate against a memcpy of the bytes its
// steps must at least move, measured in the same run.
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/voxel_triangles.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tools/bench.h"

namespace voxgi::tools {
namespace {

// The bytes one propagation step reads and writes at least: the previous volume, the next, the
// accumulated one twice, and the geometry volume when occluded.
double stepBytes(int n, int coefficients, bool occluded) {
  const double cells = double(n) * n * n;
  return cells * (4.0 * 3 * coefficients * 4 + (occluded ? 16.0 : 0.0));
}

// The median time of a memcpy moving `bytes` (half read, half written).
double memcpySeconds(double bytes, int repeats) {
  std::vector<char> from(size_t(bytes / 2), 1), to(size_t(bytes / 2));
  return medianSeconds(repeats, [&] { std::memcpy(to.data(), from.data(), from.size()); });
}

}  // namespace

void addBenchLpvOptions(CLI::App& cmd, BenchLpvOptions& o) {
  cmd.add_option("--scenes", o.scenes, "scene files")->delimiter(',');
  cmd.add_option("--resolutions", o.resolutions, "grid resolutions")->delimiter(',');
  cmd.add_option("--steps", o.steps, "propagation step counts")->delimiter(',');
  cmd.add_option("--threads-list", o.threads, "CPU thread counts")->delimiter(',');
  cmd.add_option("--repeat", o.repeats, "runs per measurement (the median is reported)")
      ->check(CLI::Range(1, 100));
  addGpuColumnOptions(cmd, o.gpu, o.gl);
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

int runBenchLpv(const BenchLpvOptions& o) {
  std::unique_ptr<gpu::GlContext> context;
  if (o.gpu) context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
  nlohmann::json rows = nlohmann::json::array();
  std::cout << std::left << std::setw(18) << "scene" << std::setw(7) << "tech" << std::setw(6)
            << "grid" << std::setw(6) << "steps" << std::setw(6) << "occl" << std::setw(12)
            << "backend" << std::setw(22) << "stage" << std::right << std::setw(10) << "seconds\n";
  // propagate seconds by (scene, grid, steps, occlusion, backend, technique)
  std::map<std::tuple<std::string, int, int, bool, std::string, std::string>, double> propagate;
  for (const std::string& file : o.scenes)
    for (int n : o.resolutions)
      for (int steps : o.steps)
        for (bool occluded : {true, false})
          for (const char* name : {"lpv", "holpv"}) {
            Scene scene = loadScene(file);
            scene.grid.resolution = n;
            const Technique& technique = findTechnique(name);
            const Settings settings =
                resolveSettings(technique, scene.settings, scene.file, "default",
                                {"propagate.steps=" + std::to_string(steps),
                                 std::string("propagate.occlusion=") + (occluded ? "on" : "off")});
            const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
            const StageContext ctx{technique, scene, settings, tris};
            cpu::CpuBackend cpuBackend;
            std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> runs;
            for (int t : o.threads) {
              tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(t));
              tbb::task_arena arena(t);
              runs.emplace_back("cpu " + std::to_string(t) + " thr", arena.execute([&] {
                return timeStages(ctx, o.repeats, cpuBackend);
              }));
            }
            if (context) {
              gpu::GpuBackend gpuBackend(*context);
              runs.emplace_back("gpu " + o.gl, timeStages(ctx, o.repeats, gpuBackend));
            }
            const std::string sceneName = std::filesystem::path(file).stem().string();
            for (const auto& [backend, stages] : runs)
              for (const auto& [stage, seconds] : stages) {
                std::cout << std::left << std::setw(18) << sceneName << std::setw(7) << name
                          << std::setw(6) << n << std::setw(6) << steps << std::setw(6)
                          << (occluded ? "on" : "off") << std::setw(12) << backend << std::setw(22)
                          << stage << std::right << std::setw(10) << std::fixed
                          << std::setprecision(4) << seconds << "\n";
                rows.push_back({{"scene", sceneName},
                                {"technique", name},
                                {"grid", n},
                                {"steps", steps},
                                {"occlusion", occluded},
                                {"backend", backend},
                                {"stage", stage},
                                {"seconds", seconds}});
                if (stage == "lpv/propagate")
                  propagate[{sceneName, n, steps, occluded, backend, name}] = seconds;
              }
          }
  nlohmann::json ratios = nlohmann::json::array();
  std::cout << "\npropagate: HOLPV / LPV, and each against a memcpy of the bytes its steps move\n";
  for (const auto& [key, lpvSeconds] : propagate) {
    const auto& [sceneName, n, steps, occluded, backend, name] = key;
    if (name != "lpv") continue;
    const double holpvSeconds = propagate.at({sceneName, n, steps, occluded, backend, "holpv"});
    const double lpvBound = memcpySeconds(stepBytes(n, 4, occluded), o.repeats) * steps;
    const double holpvBound = memcpySeconds(stepBytes(n, 9, occluded), o.repeats) * steps;
    std::cout << sceneName << " " << n << "^3, " << steps << " steps, occlusion "
              << (occluded ? "on" : "off") << ", " << backend << ": lpv " << lpvSeconds * 1e3
              << " ms (memcpy bound " << lpvBound * 1e3 << " ms), holpv " << holpvSeconds * 1e3
              << " ms (bound " << holpvBound * 1e3 << " ms), ratio " << holpvSeconds / lpvSeconds
              << "\n";
    ratios.push_back({{"scene", sceneName},
                      {"grid", n},
                      {"steps", steps},
                      {"occlusion", occluded},
                      {"backend", backend},
                      {"lpv_seconds", lpvSeconds},
                      {"holpv_seconds", holpvSeconds},
                      {"lpv_memcpy_bound_seconds", lpvBound},
                      {"holpv_memcpy_bound_seconds", holpvBound}});
  }
  std::cout << "\nmemory of one SH volume (f32; the thesis's f16 is half):\n";
  for (int n : o.resolutions)
    for (int coefficients : {4, 9})
      std::cout << "  " << n << "^3, " << coefficients << " coefficients x 3 colours: "
                << double(n) * n * n * 3 * coefficients * 4 / (1 << 20) << " MiB\n";
  if (!o.json.empty())
    writeFileAtomically(o.json,
                        nlohmann::json{{"stages", rows}, {"propagate", ratios}}.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools
