// voxgi dump: every buffer of a stage (or all) as .vdb/.exr, or its checksums.
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>

#include "common/io/buffer_io.h"
#include "common/error.h"
#include "common/fnv1a.h"
#include "common/io/output_file.h"
#include "common/scene_motion.h"
#include "tools/command.h"
#include "tools/frames.h"

namespace voxgi::tools {
namespace {

struct DumpOptions {
  SceneOptions scene;
  std::string stage = "all", out;
  bool checksums = false;
  std::string frames;  // --frames A:B[:STEP]: every frame of an animated scene
  double fps = 24.0;
};

// A stage the plan skips has no buffers: say so instead of writing another stage's.
void requirePlanned(const SceneOptions& o, const Technique& technique, const StageSpec& s) {
  const Scene scene = o.load();
  const EffectPlan plan = technique.plan(scene, o.settings(scene, true));
  if (!plan.runs(s.id))
    throw InputError("--stage", "",
                     "the plan skips " + s.qualifiedName() + " (" + plan.whySkipped(s.id) +
                         "), so it has no buffers to dump (voxgi plan shows why)");
}

void printChecksums(const std::vector<const Buffer*>& buffers) {
  for (const Buffer* b : buffers)
    std::cout << "checksum " << b->spec->qualifiedName() << " " << b->words.size() << " "
              << std::hex << std::setw(16) << std::setfill('0')
              << fnv1a(b->words.data(), b->words.size() * sizeof(uint32_t)) << std::dec
              << std::setfill(' ') << "\n";
}

// One frame's buffers: checksums printed, files written as <out>/<stage><suffix>.vdb (and .exr).
void dumpFrame(const DumpOptions& o, const Technique& technique, const StageSpec* only, Scene scene,
               const std::string& suffix) {
  const StageRun run = runStages(o.scene, std::move(scene), only, true);
  for (const StageSpec* s : run.stages) {
    if (only != nullptr && s != only) continue;
    if (o.checksums) printChecksums(buffersOf(run.buffers, *s, true));
    if (o.out.empty()) continue;
    for (const std::string& path :
         writeBuffers(o.out + "/" + std::string(s->name) + suffix, buffersOf(run.buffers, *s, true),
                      run.scene.grid, {}, technique.sparseLayouts(run.buffers, run.scene.grid)))
      std::cout << "wrote " << path << "\n";
  }
}

int runDump(const DumpOptions& o) {
  if (o.out.empty() && !o.checksums)
    throw InputError("--out", "", "dump needs an output folder (--out) or --checksums");
  const Technique& technique = findTechnique(o.scene.technique);
  const bool all = o.stage == "all";
  const std::vector<const StageSpec*> requested = requestedStages(technique, o.stage);
  if (!all) requirePlanned(o.scene, technique, *requested.front());
  const FrameRange range = o.frames.empty() ? FrameRange{} : parseFrames(o.frames, "--frames");
  if (!o.out.empty()) prepareOutputFolder(o.out);
  const StageSpec* only = all ? nullptr : requested.front();
  const Scene scene = o.scene.load();
  if (o.frames.empty()) {
    dumpFrame(o, technique, only, scene, "");
    return kExitOk;
  }
  // Each frame from scratch, its files numbered as Blender and Houdini read a volume sequence
  // (voxelize_0012.vdb).
  for (int f = range.first; f <= range.last; f += range.step) {
    if (o.checksums) std::cout << "frame " << f << "\n";
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "_%04d", f);
    dumpFrame(o, technique, only,
              scene.motion.empty() ? scene : sceneAt(scene, frameSeconds(f, o.fps)), suffix);
  }
  return kExitOk;
}

}  // namespace

void addDumpCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<DumpOptions>();
  CLI::App* cmd = app.add_subcommand("dump", "write every buffer of a stage (or all) as .vdb/.exr");
  o->scene.add(*cmd, globals, true);
  o->scene.addTechnique(*cmd);
  cmd->add_option("--stage", o->stage, kStageHelp)->required();
  cmd->add_option("--out", o->out, "output folder");
  cmd->add_flag("--checksums", o->checksums,
                "print each buffer's word count and FNV-1a checksum (a run's fingerprint, to "
                "check that a change or another machine reproduces it bit for bit)");
  cmd->add_option("--frames", o->frames,
                  "dump frames A to B (A:B or A:B:STEP) of an animated scene, each from scratch, "
                  "as <stage>_%04d.vdb (docs/motion.md)");
  cmd->add_option("--fps", o->fps, "frames per second of --frames")->check(CLI::Range(1e-3, 1e6));
  commands.push_back({cmd, [o] { return runDump(*o); }});
}

}  // namespace voxgi::tools
