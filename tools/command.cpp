#include "tools/command.h"

#include <chrono>
#include <iostream>

#include "common/error.h"
#include "common/scene_io/scene_load.h"

namespace voxgi::tools {

void SceneOptions::add(CLI::App& cmd, Globals& globals, bool withBackend) {
  cmd.add_option("scene", scene, "scene .json or mesh file (OBJ, glTF, PLY)")->required();
  // Given explicitly, 0 is an error, not "the scene's" (which is what leaving them out means).
  cmd.add_option("--resolution", resolution, "voxel grid resolution (power of two)")
      ->check(CLI::Range(1, kMaxResolution));
  cmd.add_option("--image", image, "image width in pixels (the height keeps the aspect)")
      ->check(CLI::Range(1, 16384));
  cmd.add_option("--mode", mode,
                 "voxelization: conservative or antialiased (default: voxelize.mode)")
      ->check(CLI::IsMember({"conservative", "antialiased"}));
  cmd.add_option("--gl", gl, "GL platform for the GPU backend")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  if (withBackend)
    cmd.add_option("--backend", backend, "cpu, gpu or auto (hardware GPU if present, else cpu)")
        ->check(CLI::IsMember({"cpu", "gpu", "auto"}));
  cmd.add_option("--threads", globals.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd.add_option("--camera", camera,
                 "a camera of the scene's glTF files by node name (default: the scene file's, "
                 "else the first)");
  cmd.add_option("--preset", preset, "parameter preset of the technique (render --help)");
  cmd.add_option("--set", sets, "technique parameter key=value (repeatable; see render --help)");
}

void SceneOptions::addTechnique(CLI::App& cmd) {
  cmd.add_option("--technique", technique, "technique: " + techniqueNames())
      ->check(CLI::IsMember(techniqueList()));
}

Scene SceneOptions::load() const {
  Scene s = loadScene(scene, {.camera = camera});
  if (resolution != 0) {
    s.grid.resolution = readResolution("--resolution", "", resolution);
    checkGrid(s, "--resolution " + std::to_string(resolution));
  }
  if (image != 0) setImageWidth(s, image, "--image");
  return s;
}

Settings SceneOptions::settings(const Scene& s, bool inspect) const {
  std::vector<std::string> all = sets;
  if (!mode.empty()) all.insert(all.begin(), "voxelize.mode=" + mode);
  Settings out = resolveSettings(findTechnique(technique), s.settings, s.file, preset, all);
  out.inspect = inspect;
  return out;
}

std::string lightingNote(const Scene& scene) {
  if (scene.defaultLights)
    return printable(scene.file) +
           ": nothing in the file emits light: lit by voxgi's default key and fill lights "
           "(docs/scene-format.md, \"Default lights\")";
  if (scene.unlit())
    return "warning: " + printable(scene.file) +
           ": nothing emits light (no light, no emissive material, a black background), so the "
           "image is black";
  return {};
}

std::vector<std::string> techniqueList() {
  std::vector<std::string> names;
  for (const Technique& t : techniques()) names.emplace_back(t.name);
  return names;
}

std::string StageRun::backendName() const {
  return backend.gpu ? "gpu: " + backend.context->renderer() : "cpu";
}

StageRun runStages(const SceneOptions& o, const StageSpec* last, bool inspect) {
  // Input first: a bad scene or --set fails before any backend starts.
  findTechnique(o.technique);
  return runStages(o, o.load(), last, inspect);
}

StageRun runStages(const SceneOptions& o, Scene scene, const StageSpec* last, bool inspect) {
  const Technique& technique = findTechnique(o.technique);
  const Settings settings = o.settings(scene, inspect);
  StageRun run{std::move(scene),
               settings,
               chooseBackend(o.backend, gpu::parseGlPlatform(o.gl)),
               {},
               {},
               {},
               0.0};
  if (!run.backend.note.empty()) std::cerr << "voxgi: " << run.backend.note << "\n";
  const auto start = std::chrono::steady_clock::now();
  run.triangles = prepareVoxelTriangles(run.scene, run.scene.grid);
  const StageContext ctx{technique, run.scene, run.settings, run.triangles};
  runPipeline(run.backend.stages(), ctx, run.buffers, last,
              [&](const StageSpec& stage, double) { run.stages.push_back(&stage); });
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::vector<const Buffer*> buffersOf(const BufferSet& set, const StageSpec& stage, bool withSums) {
  std::vector<const Buffer*> out;
  for (const BufferSpec* spec : stageBuffers(stage)) {
    const Buffer* b = set.find(spec->id);
    const bool floats = spec->type == ScalarType::f32 || spec->type == ScalarType::f16;
    if (b == nullptr || (!withSums && !floats)) continue;
    out.push_back(b);
  }
  return out;
}

std::vector<const StageSpec*> requestedStages(const Technique& technique,
                                              const std::string& stage) {
  if (stage == "all") return technique.steps();
  return {&resolveStage(technique, stage)};
}

}  // namespace voxgi::tools
