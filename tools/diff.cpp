// voxgi diff: the stages on both backends, every buffer compared through its registered
// comparison (validation/comparisons.inc); exit 1 when one fails.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/output_file.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "common/scene_motion.h"
#include "tools/command.h"
#include "tools/frames.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::tools {
namespace {

struct DiffOptions {
  SceneOptions scene;
  std::string stage = "all", json, dumpDir;
  std::string frames;  // --frames A:B[:STEP]: every frame of an animated scene
  double fps = 24.0;
};

int runDiff(const DiffOptions& o) {
  const Technique& technique = findTechnique(o.scene.technique);
  const Scene scene = o.scene.load();
  const std::vector<const StageSpec*> stages = requestedStages(technique, o.stage);
  std::vector<int> frames{0};
  if (!o.frames.empty()) {
    const FrameRange range = parseFrames(o.frames, "--frames");
    frames.clear();
    for (int f = range.first; f <= range.last; f += range.step) frames.push_back(f);
  }
  if (!o.json.empty()) checkOutputPath(o.json);
  if (!o.dumpDir.empty()) prepareOutputFolder(o.dumpDir);
  auto context = gpu::GlContext::create(gpu::parseGlPlatform(o.scene.gl));
  std::cerr << "voxgi: diff on " << context->renderer() << "\n";
  cpu::CpuBackend cpuBackend;
  gpu::GpuBackend gpuBackend(*context);
  // Each frame of the scene at its time, from scratch on both backends but for the light a stage
  // carries from the frame before; an animated scene without --frames is its frame 0.
  bool pass = true;
  nlohmann::json json = nlohmann::json::array();
  FrameHistory history;  // what stages carry from frame to frame (propagate.carry)
  for (const int f : frames) {
    const Scene at = scene.motion.empty() ? scene : sceneAt(scene, frameSeconds(f, o.fps));
    const Settings settings = o.scene.settings(at, true);
    const VoxelTriangles triangles = prepareVoxelTriangles(at, at.grid);
    StageContext ctx{technique, at, settings, triangles};
    if (!o.frames.empty()) ctx.history = &history;
    std::string dump = o.dumpDir;
    if (!dump.empty() && !o.frames.empty()) {
      dump = o.dumpDir + "/frame_" + std::to_string(f);
      prepareOutputFolder(dump);
    }
    const auto reports = validation::diffStages(ctx, cpuBackend, gpuBackend, stages, dump);
    if (!o.frames.empty()) std::cout << "frame " << f << ":\n";
    validation::printReport(std::cout, reports);
    json.push_back({{"frame", f}, {"stages", validation::toJson(reports)}});
    for (const auto& r : reports) pass &= r.pass;
  }
  if (!o.json.empty())
    writeFileAtomically(o.json, (o.frames.empty() ? json[0]["stages"] : json).dump(2) + "\n");
  return pass ? kExitOk : kExitInternal;
}

}  // namespace

void addDiffCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<DiffOptions>();
  CLI::App* cmd =
      app.add_subcommand("diff", "run stages on both backends and compare every buffer");
  o->scene.add(*cmd, globals, false);
  o->scene.addTechnique(*cmd);
  cmd->add_option("--stage", o->stage, kStageHelp);
  cmd->add_option("--json", o->json, "write the report as JSON");
  cmd->add_option("--dump", o->dumpDir,
                  "write cpu, gpu and difference grids (.vdb) here (with --frames, one folder "
                  "frame_F per frame)");
  cmd->add_option("--frames", o->frames,
                  "diff frames A to B (A:B or A:B:STEP) of an animated scene, each from scratch "
                  "on both backends but for what stages carry from frame to frame "
                  "(propagate.carry, given to both as the CPU found it; docs/motion.md)");
  cmd->add_option("--fps", o->fps, "frames per second of --frames")->check(CLI::Range(1e-3, 1e6));
  commands.push_back({cmd, [o] { return runDiff(*o); }});
}

}  // namespace voxgi::tools
