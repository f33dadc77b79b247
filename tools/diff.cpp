// voxgi diff: the stages on both backends, every buffer compared through its registered
// comparison (validation/comparisons.inc); exit 1 when one fails.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/output_file.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tools/command.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::tools {
namespace {

struct DiffOptions {
  SceneOptions scene;
  std::string stage = "all", json, dumpDir;
};

int runDiff(const DiffOptions& o) {
  const Technique& technique = findTechnique(o.scene.technique);
  const Scene scene = o.scene.load();
  const Settings settings = o.scene.settings(scene, true);
  const std::vector<const StageSpec*> stages = requestedStages(technique, o.stage);
  if (!o.json.empty()) checkOutputPath(o.json);
  if (!o.dumpDir.empty()) prepareOutputFolder(o.dumpDir);
  auto context = gpu::GlContext::create(gpu::parseGlPlatform(o.scene.gl));
  std::cerr << "voxgi: diff on " << context->renderer() << "\n";
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{technique, scene, settings, triangles};
  cpu::CpuBackend cpuBackend;
  gpu::GpuBackend gpuBackend(*context);
  const auto reports = validation::diffStages(ctx, cpuBackend, gpuBackend, stages, o.dumpDir);
  validation::printReport(std::cout, reports);
  if (!o.json.empty()) writeFileAtomically(o.json, validation::toJson(reports).dump(2) + "\n");
  bool pass = true;
  for (const auto& r : reports) pass &= r.pass;
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
  cmd->add_option("--dump", o->dumpDir, "write cpu, gpu and difference grids (.vdb) here");
  commands.push_back({cmd, [o] { return runDiff(*o); }});
}

}  // namespace voxgi::tools
