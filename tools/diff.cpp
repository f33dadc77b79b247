// voxgi diff: the stages on both backends, every buffer compared through its registered
// comparison (validation/comparisons.inc); exit 1 when one fails.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/vdb_io.h"
#include "common/io/output_file.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "common/scene_motion.h"
#include "tools/command.h"
#include "tools/frames.h"
#include "validation/check.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::tools {
namespace {

struct DiffOptions {
  SceneOptions scene;
  std::string stage = "all", json, dumpDir;
  std::string frames;  // --frames A:B[:STEP]: every frame of an animated scene
  double fps = 24.0;
  std::string against;  // --against DIR: dumps written elsewhere instead of the GPU backend
};

// The buffers of `stage` a dump folder holds, as `voxgi dump` names them: its volumes from
// DIR/<stage>.vdb and its RGB float images from DIR/<stage>.<buffer>.exr. Other shapes do not
// survive a dump word for word (pyramids and the octree's pools are placed by level, 1- and
// 4-component images lose channels): voxgi.check takes those as arrays (docs/python.md).
BufferSet dumpedBuffers(const std::string& dir, const StageSpec& stage, const Scene& scene) {
  namespace fs = std::filesystem;
  BufferSet out;
  std::vector<const BufferSpec*> volumes;
  for (const BufferSpec* spec : stageBuffers(stage))
    if (spec->shape == BufferShape::volume) volumes.push_back(spec);
  const std::string vdb = dir + "/" + std::string(stage.name) + ".vdb";
  if (!volumes.empty() && fs::exists(vdb)) {
    GridSpec grid;
    for (const auto& [id, b] : readVdb(vdb, grid, volumes)) {
      if (grid.resolution != scene.grid.resolution)
        throw InputError(vdb, "voxgi_resolution",
                         std::to_string(grid.resolution) + "^3, the scene's grid is " +
                             std::to_string(scene.grid.resolution) + "^3 (--resolution)");
      out.put(b);
    }
  }
  for (const BufferSpec* spec : stageBuffers(stage)) {
    if (spec->shape != BufferShape::image || spec->type != ScalarType::f32 || spec->components != 3)
      continue;
    const std::string exr =
        dir + "/" + std::string(stage.name) + "." + std::string(spec->name) + ".exr";
    if (!fs::exists(exr)) continue;
    const Image image = readExr(exr);
    if (image.width != scene.camera.width || image.height != scene.camera.height)
      throw InputError(exr, "",
                       std::to_string(image.width) + "x" + std::to_string(image.height) +
                           ", the scene's camera " + std::to_string(scene.camera.width) + "x" +
                           std::to_string(scene.camera.height) + " (--image)");
    Buffer b(*spec, {image.width, image.height, 1});
    for (size_t e = 0; e < image.pixels.size(); ++e) b.setVec3(e, image.pixels[e]);
    out.put(std::move(b));
  }
  return out;
}

// --against: each requested stage's dumped buffers against the CPU oracle's, through their
// registered comparisons. A stage with nothing in DIR is reported as such; finding nothing at all
// fails (a wrong folder must not pass).
int runDiffAgainst(const DiffOptions& o) {
  if (!o.frames.empty()) throw InputError("--against", "", "one frame at a time (no --frames)");
  if (!std::filesystem::is_directory(o.against))
    throw InputError(o.against, "", "--against: not a folder");
  const Technique& technique = findTechnique(o.scene.technique);
  const Scene scene = o.scene.load();
  const std::vector<const StageSpec*> stages = requestedStages(technique, o.stage);
  if (!o.json.empty()) checkOutputPath(o.json);
  const Settings settings = o.scene.settings(scene, true);
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{technique, scene, settings, triangles};
  const StageSpec* last = nullptr;
  for (const StageSpec* s : technique.steps())
    if (std::find(stages.begin(), stages.end(), s) != stages.end()) last = s;
  cpu::CpuBackend cpuBackend;
  BufferSet oracle;
  runPipeline(cpuBackend, ctx, oracle, last);
  std::vector<validation::StageReport> reports;
  size_t compared = 0;
  for (const StageSpec* stage : stages) {
    const BufferSet candidate = dumpedBuffers(o.against, *stage, scene);
    if (!ctx.plan.runs(stage->id) || candidate.size() == 0) {
      validation::StageReport skipped;
      skipped.stage = stage->qualifiedName();
      skipped.skipped = !ctx.plan.runs(stage->id)
                            ? "skipped by the plan: " + ctx.plan.whySkipped(stage->id)
                            : "nothing of it in " + o.against;
      reports.push_back(std::move(skipped));
      continue;
    }
    compared += candidate.size();
    reports.push_back(validation::checkStage(ctx, oracle, candidate));
  }
  if (compared == 0)
    throw InputError(o.against, "",
                     "no dump of the stages asked for (voxgi dump's <stage>.vdb and "
                     "<stage>.<buffer>.exr)");
  validation::printReport(std::cout, reports);
  bool pass = true;
  for (const auto& r : reports) pass &= r.pass;
  if (!o.json.empty()) writeFileAtomically(o.json, validation::toJson(reports).dump(2) + "\n");
  return pass ? kExitOk : kExitInternal;
}

int runDiff(const DiffOptions& o) {
  if (!o.against.empty()) return runDiffAgainst(o);
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
  cmd->add_option("--against", o->against,
                  "compare the dumps in this folder (another engine's, as voxgi dump names "
                  "them: <stage>.vdb, <stage>.<buffer>.exr) with the CPU oracle instead of "
                  "running the GPU backend (docs/python.md, \"Checking your engine\")");
  commands.push_back({cmd, [o] { return runDiff(*o); }});
}

}  // namespace voxgi::tools
