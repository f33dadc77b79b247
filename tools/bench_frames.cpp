// `voxgi bench frames`: an animated scene's frames through FrameRunner, once updating each frame
// from the one before (the stages whose inputs did not change reused, voxelize updated in part)
// and once rebuilding every frame, side by side on the same backend: each stage's median time per
// frame (over the frames after the first; the median of --repeat runs of the sequence) and the
// frame's, triangle setup included.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/frame_plan.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/scene_motion.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tools/bench.h"
#include "tools/frames.h"

namespace voxgi::tools {
namespace {

constexpr const char* kFrame = "frame";  // the whole frame's row

// Seconds per frame by stage (and kFrame) over the frames after the first, for one run of the
// sequence.
std::map<std::string, double> sequenceSeconds(const Technique& technique, StageBackend& backend,
                                              bool scratch, const Scene& scene,
                                              const Settings& settings, const FrameRange& range) {
  FrameRunner runner(technique, backend, scratch);
  std::map<std::string, double> total;
  int counted = 0;
  for (int f = range.first; f <= range.last; f += range.step) {
    const bool first = f == range.first;
    Scene at = sceneAt(scene, frameSeconds(f, 24.0));
    const auto start = std::chrono::steady_clock::now();
    runner.run(std::move(at), settings, [&](const StageSpec& stage, double seconds) {
      if (!first) total[stage.qualifiedName()] += seconds;
    });
    if (first) continue;
    total[kFrame] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++counted;
  }
  for (auto& [stage, seconds] : total) seconds /= std::max(counted, 1);
  return total;
}

// The median over `repeats` runs of each row.
std::map<std::string, double> medianSequence(
    int repeats, const std::function<std::map<std::string, double>()>& run) {
  std::map<std::string, std::vector<double>> runs;
  for (int r = 0; r < repeats; ++r)
    for (const auto& [stage, seconds] : run()) runs[stage].push_back(seconds);
  std::map<std::string, double> out;
  for (auto& [stage, values] : runs) {
    values.resize(size_t(repeats), 0.0);  // a stage that did not run in a repeat: 0 there
    out[stage] = median(values);
  }
  return out;
}

}  // namespace

void addBenchFramesOptions(CLI::App& cmd, BenchFramesOptions& o) {
  cmd.add_option("--scenes", o.scenes, "animated scene files")->delimiter(',');
  cmd.add_option("--techniques", o.techniques, "techniques")->delimiter(',');
  cmd.add_option("--frames", o.frames, "frames A:B[:STEP] at 24 fps (the first is not timed)");
  cmd.add_option("--resolutions", o.resolutions, "grid resolutions")->delimiter(',');
  cmd.add_option("--threads-list", o.threads, "CPU thread counts")->delimiter(',');
  cmd.add_option("--repeat", o.repeats, "runs of each sequence (the median is reported)")
      ->check(CLI::Range(1, 100));
  addGpuColumnOptions(cmd, o.gpu, o.gl);
  cmd.add_option("--set", o.sets, "technique parameter key=value (repeatable)");
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

int runBenchFrames(const BenchFramesOptions& o) {
  const FrameRange range = parseFrames(o.frames, "--frames");
  std::unique_ptr<gpu::GlContext> context;
  if (o.gpu) context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
  nlohmann::json rows = nlohmann::json::array();
  std::cout << std::left << std::setw(20) << "scene" << std::setw(7) << "tech" << std::setw(6)
            << "grid" << std::setw(12) << "backend" << std::setw(22) << "stage" << std::right
            << std::setw(12) << "update ms" << std::setw(12) << "rebuild ms" << std::setw(9)
            << "ratio\n";
  for (const std::string& file : o.scenes)
    for (const std::string& name : o.techniques)
      for (int n : o.resolutions) {
        Scene scene = loadScene(file);
        scene.grid.resolution = n;
        checkGrid(scene, file);
        const Technique& technique = findTechnique(name);
        const Settings settings =
            resolveSettings(technique, scene.settings, scene.file, "default", o.sets);
        std::vector<std::pair<std::string, std::function<std::map<std::string, double>(bool)>>>
            backends;
        cpu::CpuBackend cpu;
        for (int t : o.threads)
          backends.emplace_back("cpu " + std::to_string(t) + " thr", [&, t](bool scratch) {
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(t));
            tbb::task_arena arena(t);
            return arena.execute(
                [&] { return sequenceSeconds(technique, cpu, scratch, scene, settings, range); });
          });
        std::unique_ptr<gpu::GpuBackend> gpuBackend;
        if (context) {
          gpuBackend = std::make_unique<gpu::GpuBackend>(*context);
          backends.emplace_back("gpu " + o.gl, [&](bool scratch) {
            return sequenceSeconds(technique, *gpuBackend, scratch, scene, settings, range);
          });
        }
        const std::string sceneName = std::filesystem::path(file).stem().string();
        for (const auto& [backend, sequence] : backends) {
          // A named reference: clang 14 (clang-tidy) cannot capture a structured binding.
          const auto& run = sequence;
          const auto update = medianSequence(o.repeats, [&] { return run(false); });
          const auto rebuild = medianSequence(o.repeats, [&] { return run(true); });
          for (const auto& [stage, rebuilt] : rebuild) {
            const auto it = update.find(stage);
            const double updated = it == update.end() ? 0.0 : it->second;
            std::cout << std::left << std::setw(20) << sceneName << std::setw(7) << name
                      << std::setw(6) << n << std::setw(12) << backend << std::setw(22) << stage
                      << std::right << std::fixed << std::setprecision(2) << std::setw(12)
                      << updated * 1e3 << std::setw(12) << rebuilt * 1e3 << std::setw(9)
                      << std::setprecision(3) << updated / rebuilt << "\n";
            rows.push_back({{"scene", sceneName},
                            {"technique", name},
                            {"grid", n},
                            {"backend", backend},
                            {"stage", stage},
                            {"update_seconds", updated},
                            {"rebuild_seconds", rebuilt}});
          }
        }
      }
  if (!o.json.empty()) writeFileAtomically(o.json, nlohmann::json{{"frames", rows}}.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools
