// voxgi plan: the stages and effects a technique's plan runs for a scene, and why each is in or
// out (docs/effect-plan.md).
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "common/error.h"
#include "common/frame_plan.h"
#include "tools/command.h"
#include "tools/frames.h"

namespace voxgi::tools {
namespace {

struct PlanOptions {
  SceneOptions scene;
  std::string frames;  // --frames A:B[:STEP]: the plan in time
  double fps = 24.0;
};

// Per frame of --frames: what moved since the frame before, and which stages run or reuse their
// buffers, as `voxgi render --frames` runs them (update.interval included: FrameRunner's steps on
// a backend that runs nothing).
class PlanOnly : public StageBackend {
 public:
  std::string name() const override { return "plan"; }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override {
    putDarkOutputs(ctx, stage, buffers);  // zero buffers of the planned sizes: nothing computed
  }
};

void printFramePlans(const PlanOptions& o, const Technique& technique, const Scene& scene) {
  const FrameRange range = parseFrames(o.frames, "--frames");
  PlanOnly backend;
  FrameRunner runner(technique, backend);
  for (int f = range.first; f <= range.last; f += range.step) {
    const double seconds = frameSeconds(f, o.fps);
    Scene at = sceneAt(scene, seconds);
    const Settings settings = o.scene.settings(at);
    const std::vector<FrameStep>& steps = runner.run(std::move(at), settings);
    std::cout << "\nframe " << f << " (" << seconds << " s): " << runner.why() << "\n";
    for (const FrameStep& s : steps)
      std::cout << "  " << (s.runs ? "run  " : "reuse") << "  " << std::left << std::setw(20)
                << s.stage->qualifiedName() << "  " << s.why << "\n";
  }
}

int runPlan(const PlanOptions& options) {
  const SceneOptions& o = options.scene;
  const Technique& technique = findTechnique(o.technique);
  const Scene scene = o.load();
  const EffectPlan plan = technique.plan(scene, o.settings(scene));
  std::cout << technique.name << " plan for " << scene.file << " (" << scene.grid.resolution
            << "^3 grid, " << scene.camera.width << "x" << scene.camera.height << " image):\n";
  if (const std::string note = lightingNote(scene); !note.empty())
    std::cout << "  lights: " << note << "\n";
  for (const PlanItem& item : plan.items)
    std::cout << "  " << (item.in ? "in " : "out") << "  " << std::left << std::setw(20)
              << item.name << "  " << item.why << "\n";
  if (!options.frames.empty()) printFramePlans(options, technique, scene);
  return kExitOk;
}

}  // namespace

void addPlanCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "print the stages and effects a technique's plan runs for a scene, and why each is "
      "in or out");
  o->scene.add(*cmd, globals, false);
  o->scene.addTechnique(*cmd);
  cmd->add_option("--frames", o->frames,
                  "also say, for frames A to B (A:B or A:B:STEP) of an animated scene, which "
                  "stages each frame runs and which reuse the frame before's buffers, and why "
                  "(docs/motion.md)");
  cmd->add_option("--fps", o->fps, "frames per second of --frames")->check(CLI::Range(1e-3, 1e6));
  commands.push_back({cmd, [o] { return runPlan(*o); }});
}

}  // namespace voxgi::tools
