// The commands of the voxgi binary (docs/architecture.md, "Command line"), one file each
// (tools/<command>.cpp), and the options and helpers the scene-taking ones share. Each file adds
// its subcommand, its options and what it runs; tools/voxgi.cpp parses and runs the one given.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/pipeline.h"
#include "common/scene.h"
#include "common/settings.h"
#include "common/voxel_triangles.h"
#include "tools/backend.h"

namespace voxgi::tools {

// A subcommand and what it runs once parsed (its exit status).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};
using Commands = std::vector<Command>;

// Options every command takes; --threads is also the binary's own.
struct Globals {
  int threads = 0;  // 0: all cores
};

void addRenderCommand(CLI::App& app, Globals& globals, Commands& commands);
void addPlanCommand(CLI::App& app, Globals& globals, Commands& commands);
void addDiffCommand(CLI::App& app, Globals& globals, Commands& commands);
void addDumpCommand(CLI::App& app, Globals& globals, Commands& commands);
void addVoxelizeCommand(CLI::App& app, Globals& globals, Commands& commands);
void addLedgerCommand(CLI::App& app, Globals& globals, Commands& commands);
void addSampleCommand(CLI::App& app, Commands& commands);
void addCompareCommand(CLI::App& app, Commands& commands);
void addStudyCommand(CLI::App& app, Commands& commands);
void addBenchCommand(CLI::App& app, Commands& commands);

// The options of the commands that take a scene.
struct SceneOptions {
  std::string scene;
  std::string technique = "vct";
  int resolution = 0;  // 0: the scene's
  int image = 0;       // image width; 0: the scene's
  std::string mode;    // empty: the settings' voxelize.mode
  std::string backend = "auto";
  std::string gl = "egl";
  std::string preset = "default";
  std::string camera;             // --camera NAME: a camera of the scene's glTF files
  std::vector<std::string> sets;  // --set key=value, applied last

  // The scene and its overrides, --gl, --threads, --preset and --set; --backend when `backend`.
  void add(CLI::App& cmd, Globals& globals, bool backend);
  // --technique, one of the registry's.
  void addTechnique(CLI::App& cmd);
  // The scene file with --resolution and --image applied.
  Scene load() const;
  // The scene file's "settings", the preset, --mode and --set, the later choice winning;
  // `inspect` for diff and dump (Settings::inspect).
  Settings settings(const Scene& scene, bool inspect = false) const;
};

// How the scene is lit when its file does not say (the default lights, or a warning that nothing
// emits light), for render and plan to print once the run has succeeded; empty otherwise.
std::string lightingNote(const Scene& scene);

// The technique names of the registry, for --technique's check.
std::vector<std::string> techniqueList();

// The stages up to `last` (all when null) on the backend the options pick (saying why when auto
// falls back).
struct StageRun {
  Scene scene;
  Settings settings;
  BackendChoice backend;
  VoxelTriangles triangles;  // prepareVoxelTriangles(scene, scene.grid), as the stages saw them
  BufferSet buffers;
  std::vector<const StageSpec*> stages;  // those the plan ran
  double seconds = 0.0;                  // running them
  std::string backendName() const;
};
StageRun runStages(const SceneOptions& o, const StageSpec* last, bool inspect = false);
// The same on a scene already loaded (one frame of a sequence: sceneAt).
StageRun runStages(const SceneOptions& o, Scene scene, const StageSpec* last, bool inspect = false);

// The buffers `stage` left in the set (with the fixed-point sums only when asked).
std::vector<const Buffer*> buffersOf(const BufferSet& set, const StageSpec& stage, bool withSums);
// The stages --stage names: every step of the technique for "all", else the one it resolves to.
std::vector<const StageSpec*> requestedStages(const Technique& technique, const std::string& stage);
// --stage's help.
inline constexpr const char* kStageHelp =
    "stage (vct/trace_cones, or trace_cones within --technique) or all";

}  // namespace voxgi::tools
