// voxgi ledger SCENE --technique lpv|holpv: where a light propagation volume's light goes, step
// by step (validation/lpv/ledger.h), as a table and as JSON.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/output_file.h"
#include "tools/command.h"
#include "validation/lpv/ledger.h"

namespace voxgi::tools {
namespace {

double luminance(const glm::dvec3& c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

nlohmann::json rgb(const glm::dvec3& c) {
  return {c.r, c.g, c.b};
}

// Fractions of the emitted flux, luminance-weighted (Rec. 709) so one column stands for a colour.
void printLedger(std::ostream& out, const validation::Ledger& l) {
  const double emitted = luminance(l.emitted);
  const auto share = [&](const glm::dvec3& c) {
    return emitted > 0.0 ? luminance(c) / emitted : 0.0;
  };
  glm::dvec3 removed(0.0), left(0.0), read = l.readInjected;
  for (const validation::LedgerStep& s : l.steps) {
    removed += s.removed;
    left += s.left;
    read += s.read;
  }
  const glm::dvec3 inFlight = l.steps.empty() ? l.injected : l.steps.back().volume;
  out << std::setprecision(4) << "emitted flux (luminance) " << emitted
      << "; every figure below is a fraction of it\n"
      << "  injected into the grid " << share(l.injected) << "\n"
      << "  step      sent   removed      left   arrived  (stage's)      read\n";
  const auto cell = [](double v) {
    std::ostringstream text;
    text << std::setprecision(4) << v;
    return std::string(std::max(0, 10 - int(text.str().size())), ' ') + text.str();
  };
  out << "  " << std::setw(4) << 0 << cell(0) << cell(0) << cell(0) << cell(share(l.injected))
      << cell(share(l.injected)) << cell(share(l.readInjected)) << "\n";
  for (const validation::LedgerStep& s : l.steps)
    out << "  " << std::setw(4) << s.step << cell(share(s.sent)) << cell(share(s.removed))
        << cell(share(s.left)) << cell(share(s.arrived)) << cell(share(s.volume))
        << cell(share(s.read)) << "\n";
  out << "  total removed by the geometry volume " << share(removed) << ", left the grid "
      << share(left) << ", still in the volume after the last step " << share(inFlight) << "\n"
      << "  read by shading over every surface: " << share(l.read)
      << " (steps summed: " << share(read) << "; a closed box's surfaces receive 1 of the "
      << "emitters' direct light)\n"
      << "  per surface (read / emitted, and per unit of area relative to the whole scene's):\n";
  double area = 0.0;
  for (const validation::LedgerSurface& s : l.surfaces) area += s.area;
  for (const validation::LedgerSurface& s : l.surfaces)
    out << "    " << std::left << std::setw(44) << s.name << std::right << cell(share(s.read))
        << cell(area > 0.0 && s.area > 0.0 && luminance(l.read) > 0.0
                    ? luminance(s.read) / s.area / (luminance(l.read) / area)
                    : 0.0)
        << "\n";
}

nlohmann::json ledgerJson(const validation::Ledger& l) {
  nlohmann::json steps = nlohmann::json::array();
  for (const validation::LedgerStep& s : l.steps)
    steps.push_back({{"step", s.step},
                     {"sent", rgb(s.sent)},
                     {"removed", rgb(s.removed)},
                     {"left", rgb(s.left)},
                     {"arrived", rgb(s.arrived)},
                     {"volume", rgb(s.volume)},
                     {"read", rgb(s.read)}});
  nlohmann::json surfaces = nlohmann::json::array();
  for (const validation::LedgerSurface& s : l.surfaces)
    surfaces.push_back({{"name", s.name}, {"area", s.area}, {"read", rgb(s.read)}});
  return {{"emitted", rgb(l.emitted)},
          {"injected", rgb(l.injected)},
          {"read_injected", rgb(l.readInjected)},
          {"steps", steps},
          {"read", rgb(l.read)},
          {"surfaces", surfaces},
          {"samples_per_cell", l.samplesPerCell}};
}

struct LedgerOptions {
  SceneOptions scene;
  std::string json;
};

// A light propagation volume run up to propagate, with every step kept.
int runLedger(const LedgerOptions& o) {
  const Technique& technique = findTechnique(o.scene.technique);
  const auto& steps = technique.steps();
  const StageSpec& propagate = stageSpec(StageId::lpv_propagate);
  if (std::find(steps.begin(), steps.end(), &propagate) == steps.end())
    throw InputError(
        "--technique", "",
        o.scene.technique + " has no propagation volume; the ledger is lpv's and holpv's");
  if (!o.json.empty()) checkOutputPath(o.json);
  const StageRun run = runStages(o.scene, &propagate, true);
  const StageContext ctx{technique, run.scene, run.settings, run.triangles};
  const validation::Ledger ledger = validation::lpvLedger(ctx, run.buffers);
  std::cout << technique.name << " ledger of " << run.scene.file << " ("
            << run.scene.grid.resolution << "^3, " << ledger.steps.size() << " steps, "
            << run.backendName() << ")\n";
  printLedger(std::cout, ledger);
  if (!o.json.empty()) writeFileAtomically(o.json, ledgerJson(ledger).dump(2) + "\n");
  return kExitOk;
}

}  // namespace

void addLedgerCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<LedgerOptions>();
  CLI::App* cmd = app.add_subcommand(
      "ledger",
      "light propagation volumes: per step the flux sent, removed by the geometry volume, lost at "
      "the grid's border and read by shading, against the emitted flux");
  o->scene.add(*cmd, globals, true);
  cmd->add_option("--technique", o->scene.technique, "lpv or holpv")
      ->check(CLI::IsMember(techniqueList()));
  cmd->add_option("--json", o->json, "also write the ledger as JSON");
  commands.push_back({cmd, [o] { return runLedger(*o); }});
}

}  // namespace voxgi::tools
