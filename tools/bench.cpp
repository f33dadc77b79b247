// What the benchmarks share: their command, the stage timer, medians and the GPU column's options.
#include <algorithm>
#include <chrono>
#include <memory>

#include "cpu/backend.h"
#include "tools/bench.h"
#include "tools/command.h"

namespace voxgi::tools {

std::vector<std::pair<std::string, double>> timeStages(const StageContext& ctx, int repeats,
                                                       StageBackend& backend) {
  cpu::CpuBackend reference;
  const bool onCpu = dynamic_cast<cpu::CpuBackend*>(&backend) != nullptr;
  std::vector<std::pair<std::string, double>> out;
  BufferSet inputs;
  for (const StageSpec* stage : plannedStages(ctx)) {
    if (stage->id == StageId::common_voxelize) {
      runStage(reference, *stage, ctx, inputs);
      continue;
    }
    // Copying the inputs is not timed: only the stage.
    std::vector<double> times;
    BufferSet result;
    for (int r = 0; r < repeats; ++r) {
      result = inputs;
      const auto start = std::chrono::steady_clock::now();
      const StageOutputs outputs = runStage(backend, *stage, ctx, result);
      times.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (!outputs.ok()) throw std::logic_error(outputs.describe(*stage, backend.name()));
    }
    out.emplace_back(stage->qualifiedName(), median(std::move(times)));
    if (onCpu)
      inputs = std::move(result);
    else
      runStage(reference, *stage, ctx, inputs);  // the next stage's inputs come from the CPU
  }
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double medianSeconds(int repeats, const std::function<void()>& run) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(std::move(t));
}

void addGpuColumnOptions(CLI::App& cmd, bool& gpu, std::string& gl) {
  cmd.add_flag("!--no-gpu", gpu, "skip the GPU column");
  cmd.add_option("--gl", gl,
                 "GL platform of the GPU column (osmesa: llvmpipe; egl: a hardware GPU)")
      ->check(CLI::IsMember({"egl", "osmesa"}));
}

double elapsedSeconds(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

// A subcommand of bench running `run` on options that `add` declares.
template <class Options>
void addBench(CLI::App& bench, Commands& commands, const std::string& name,
              const std::string& description, void (*add)(CLI::App&, Options&),
              int (*run)(const Options&)) {
  auto o = std::make_shared<Options>();
  CLI::App* cmd = bench.add_subcommand(name, description);
  add(*cmd, *o);
  commands.push_back({cmd, [o, run] { return run(*o); }});
}

}  // namespace

void addBenchCommand(CLI::App& app, Commands& commands) {
  CLI::App* bench = app.add_subcommand("bench", "benchmarks (see docs/benchmarks.md)");
  bench->require_subcommand(1);
  addBench(*bench, commands, "voxelize", "voxelize: CPU 1/2 threads, GPU, OpenVDB meshToVolume",
           addBenchOptions, runBenchVoxelize);
  addBench(*bench, commands, "vct",
           "every stage after voxelize: CPU per thread count and GPU; mip vs memcpy",
           addBenchVctOptions, runBenchVct);
  addBench(*bench, commands, "lpv",
           "lpv and holpv, every stage after voxelize: CPU per thread count and GPU; "
           "propagate vs memcpy",
           addBenchLpvOptions, runBenchLpv);
  addBench(*bench, commands, "svo",
           "the octree's build from a 1.4M-point cloud: CPU per depth and thread count, "
           "OpenVDB's point rasterisation beside it",
           addBenchSvoOptions, runBenchSvo);
  addBench(*bench, commands, "path",
           "the path tracer per transport: each estimator's time and error against a converged "
           "render, efficiency 1 / (seconds x MSE)",
           addBenchPathOptions, runBenchPath);
  addBench(*bench, commands, "frames",
           "an animated scene's frames: each stage's time per frame when the frame reuses and "
           "updates the frame before's buffers against rebuilding them, CPU per thread count "
           "and GPU",
           addBenchFramesOptions, runBenchFrames);
}

}  // namespace voxgi::tools
