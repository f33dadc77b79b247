// voxgi plan: the stages and effects a technique's plan runs for a scene, and why each is in or
// out (docs/effect-plan.md).
#include <iomanip>
#include <iostream>
#include <memory>

#include "common/error.h"
#include "tools/command.h"

namespace voxgi::tools {
namespace {

int runPlan(const SceneOptions& o) {
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
  return kExitOk;
}

}  // namespace

void addPlanCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "print the stages and effects a technique's plan runs for a scene, and why each is "
      "in or out");
  o->add(*cmd, globals, false);
  o->addTechnique(*cmd);
  commands.push_back({cmd, [o] { return runPlan(*o); }});
}

}  // namespace voxgi::tools
