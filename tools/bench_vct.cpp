// `voxgi bench vct`: the median time of every stage after voxelize, per scene, grid resolution,
// image size and thread count on the CPU, and on the GPU backend (OSMesa), plus the mip stage of
// a dense RGBA32F volume against memcpy of the same bytes measured in the same run.
#include <algorithm>
#include <chrono>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/pipeline.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/voxel_triangles.h"
#include "cpu/backend.h"
#include "cpu/stages.h"
#include "gpu/backend.h"
#include "tools/bench.h"

namespace voxgi::tools {

namespace {

// cpu::mip on an N^3 RGBA32F radiance volume vs std::memcpy of the same bytes, both medians.
std::pair<double, double> mipVersusMemcpy(int n, int repeats, MipMode mode) {
  Scene scene;
  scene.grid.resolution = n;
  Settings settings;
  settings.vct.mip = mode;
  BufferSet buffers;
  Buffer radiance(BufferId::vct_light_voxels_radiance, glm::ivec3(n));
  for (size_t i = 0; i < radiance.words.size(); ++i)
    radiance.words[i] = std::bit_cast<uint32_t>(float(i % 97) / 97.0f);
  std::vector<uint32_t> copy(radiance.words.size());
  const double memcpySeconds = medianSeconds(
      repeats, [&] { std::memcpy(copy.data(), radiance.words.data(), copy.size() * 4); });
  buffers.put(std::move(radiance));
  const VoxelTriangles none{};
  const StageContext ctx{findTechnique("vct"), scene, settings, none};
  // The stage function itself, not the runner: the runner drops a stage's old buffers first, and
  // this measures the in-place rebuild a pyramid gets every frame.
  const double mipSeconds = medianSeconds(repeats, [&] { cpu::vct::mip(ctx, buffers); });
  return {mipSeconds, memcpySeconds};
}

}  // namespace

void addBenchVctOptions(CLI::App& cmd, BenchVctOptions& o) {
  cmd.add_option("--scenes", o.scenes, "scene files")->delimiter(',');
  cmd.add_option("--resolutions", o.resolutions, "grid resolutions")->delimiter(',');
  cmd.add_option("--images", o.images, "square image sizes")->delimiter(',');
  cmd.add_option("--threads-list", o.threads, "CPU thread counts")->delimiter(',');
  cmd.add_option("--mip-resolution", o.mipResolution, "mip vs memcpy volume (0: skip)");
  cmd.add_option("--repeat", o.repeats, "runs per measurement (the median is reported)")
      ->check(CLI::Range(1, 100));
  addGpuColumnOptions(cmd, o.gpu, o.gl);
  cmd.add_option("--preset", o.preset, "parameter preset");
  cmd.add_option("--set", o.sets, "technique parameter key=value");
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

int runBenchVct(const BenchVctOptions& o) {
  std::unique_ptr<gpu::GlContext> context;
  if (o.gpu) context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
  nlohmann::json rows = nlohmann::json::array();
  std::cout << std::left << std::setw(14) << "scene" << std::setw(6) << "grid" << std::setw(7)
            << "image" << std::setw(14) << "backend" << std::setw(18) << "stage" << std::right
            << std::setw(10) << "seconds\n";
  for (const std::string& file : o.scenes)
    for (int n : o.resolutions)
      for (int image : o.images) {
        Scene scene = loadScene(file);
        scene.grid.resolution = n;
        scene.camera.width = scene.camera.height = image;
        const Technique& vct = findTechnique("vct");
        const Settings settings =
            resolveSettings(vct, scene.settings, scene.file, o.preset, o.sets);
        const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
        const StageContext ctx{vct, scene, settings, tris};
        cpu::CpuBackend cpuBackend;
        std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> runs;
        for (int t : o.threads) {
          tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(t));
          tbb::task_arena arena(t);
          runs.emplace_back("cpu " + std::to_string(t) + " thr",
                            arena.execute([&] { return timeStages(ctx, o.repeats, cpuBackend); }));
        }
        if (context) {
          gpu::GpuBackend gpuBackend(*context);
          runs.emplace_back("gpu " + o.gl, timeStages(ctx, o.repeats, gpuBackend));
        }
        const std::string name = std::filesystem::path(file).stem().string();
        for (const auto& [backend, stages] : runs)
          for (const auto& [stage, seconds] : stages) {
            std::cout << std::left << std::setw(14) << name << std::setw(6) << n << std::setw(7)
                      << image << std::setw(14) << backend << std::setw(18) << stage << std::right
                      << std::setw(10) << std::fixed << std::setprecision(4) << seconds << "\n";
            rows.push_back({{"scene", name},
                            {"grid", n},
                            {"image", image},
                            {"backend", backend},
                            {"stage", stage},
                            {"seconds", seconds}});
          }
      }
  nlohmann::json mip = nlohmann::json::array();
  if (o.mipResolution > 0)
    for (MipMode mode : {MipMode::isotropic, MipMode::anisotropic}) {
      const auto [mipSeconds, memcpySeconds] = mipVersusMemcpy(o.mipResolution, o.repeats, mode);
      const char* modeName = mode == MipMode::isotropic ? "isotropic" : "anisotropic";
      std::cout << "mip " << modeName << " " << o.mipResolution << "^3 RGBA32F: " << mipSeconds
                << " s, memcpy of the same bytes " << memcpySeconds << " s, ratio "
                << mipSeconds / memcpySeconds << "\n";
      mip.push_back({{"mode", modeName},
                     {"resolution", o.mipResolution},
                     {"mip_seconds", mipSeconds},
                     {"memcpy_seconds", memcpySeconds}});
    }
  if (!o.json.empty())
    writeFileAtomically(o.json, nlohmann::json{{"stages", rows}, {"mip", mip}}.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools
