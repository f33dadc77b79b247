// The voxgi command line (docs/architecture.md, "Command line"). Exit codes: 0 ok, 1 internal
// failure or a failed diff, 2 bad input (one line naming the file and field).
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <mutex>
#include <optional>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "common/buffer_io.h"
#include "common/error.h"
#include "common/fnv1a.h"
#include "common/image_io.h"
#include "common/light_terms.h"
#include "common/output_file.h"
#include "common/pipeline.h"
#include "common/scene_load.h"
#include "common/surface_sampling.h"
#include "common/svo/level_layout.h"
#include "common/memory.h"
#include "common/vdb_io.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "gpu/program.h"
#include "tools/backend.h"
#include "tools/bench.h"
#include "tools/compare.h"
#include "tools/ledger.h"
#include "tools/study.h"
#include "validation/diff.h"
#include "validation/lpv/ledger.h"
#include "validation/reference/path_trace.h"
#include "validation/report.h"

namespace voxgi::tools {

StageBackend& BackendChoice::stages() {
  if (!runner) {
    if (gpu)
      runner = std::make_unique<gpu::GpuBackend>(*context);
    else
      runner = std::make_unique<cpu::CpuBackend>();
  }
  return *runner;
}

BackendChoice chooseBackend(const std::string& backend, gpu::GlPlatform platform) {
  BackendChoice choice;
  if (backend == "cpu") return choice;
  if (backend == "gpu") {
    choice.context = gpu::GlContext::create(platform);
    choice.gpu = true;
    return choice;
  }
  try {
    auto context = gpu::GlContext::create(gpu::GlPlatform::egl);
    if (context->isHardware()) {
      choice.context = std::move(context);
      choice.gpu = true;
      return choice;
    }
    choice.note = "auto: no hardware GPU (" + context->renderer() + "), using the CPU backend";
  } catch (const gpu::GlUnavailable& e) {
    choice.note = std::string("auto: no GL context (") + e.what() + "), using the CPU backend";
  }
  return choice;
}

}  // namespace voxgi::tools

namespace {

using namespace voxgi;

std::vector<std::string> techniqueList() {
  std::vector<std::string> names;
  for (const Technique& t : techniques()) names.emplace_back(t.name);
  return names;
}

struct Common {
  std::string scene;
  std::string technique = "vct";
  int resolution = 0;  // 0: the scene's
  int image = 0;       // image width; 0: the scene's
  std::string mode;    // empty: the settings' voxelize.mode
  std::string backend = "auto";
  std::string gl = "egl";
  std::string preset = "default";
  std::vector<std::string> sets;  // --set key=value, applied last
};

// The scene file's "settings", the preset, --mode and --set, the later choice winning; `inspect`
// for diff and dump (Settings::inspect).
Settings makeSettings(const Common& c, const Scene& scene, bool inspect = false) {
  std::vector<std::string> sets = c.sets;
  if (!c.mode.empty()) sets.insert(sets.begin(), "voxelize.mode=" + c.mode);
  Settings s =
      resolveSettings(findTechnique(c.technique), scene.settings, scene.file, c.preset, sets);
  s.inspect = inspect;
  return s;
}

Scene loadWithOverrides(const Common& c) {
  Scene scene = loadScene(c.scene);
  if (c.resolution != 0) {
    scene.grid.resolution = readResolution("--resolution", "", c.resolution);
    checkGrid(scene, "--resolution " + std::to_string(c.resolution));
  }
  if (c.image != 0) setImageWidth(scene, c.image, "--image");
  return scene;
}

// The buffers `stage` left in the set (with the fixed-point sums only when asked).
std::vector<const Buffer*> buffersOf(const BufferSet& set, const StageSpec& stage, bool withSums) {
  std::vector<const Buffer*> out;
  for (const BufferSpec* spec : stageBuffers(stage)) {
    const Buffer* b = set.find(spec->id);
    if (b == nullptr || (!withSums && spec->type != ScalarType::f32)) continue;
    out.push_back(b);
  }
  return out;
}

// The stages up to `last` (all when null) on the backend the options pick (saying why when auto
// falls back).
struct StageRun {
  Scene scene;
  Settings settings;
  tools::BackendChoice backend;
  BufferSet buffers;
  std::vector<const StageSpec*> stages;  // those the plan ran
  double seconds = 0.0;                  // running them
  std::string backendName() const {
    return backend.gpu ? "gpu: " + backend.context->renderer() : "cpu";
  }
};

StageRun runStages(const Common& c, const StageSpec* last, bool inspect = false) {
  // Input first: a bad scene or --set fails before any backend starts.
  const Technique& technique = findTechnique(c.technique);
  Scene scene = loadWithOverrides(c);
  const Settings settings = makeSettings(c, scene, inspect);
  StageRun run{std::move(scene),
               settings,
               tools::chooseBackend(c.backend, gpu::parseGlPlatform(c.gl)),
               {},
               {},
               0.0};
  if (!run.backend.note.empty()) std::cerr << "voxgi: " << run.backend.note << "\n";
  const auto start = std::chrono::steady_clock::now();
  const VoxelTriangles triangles = prepareVoxelTriangles(run.scene, run.scene.grid);
  const StageContext ctx{technique, run.scene, run.settings, triangles};
  runPipeline(run.backend.stages(), ctx, run.buffers, last,
              [&](const StageSpec& stage, double) { run.stages.push_back(&stage); });
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

int cmdVoxelize(const Common& c, const std::string& out, bool sums) {
  checkOutputPath(out);
  const StageSpec& voxelize = stageSpec(StageId::common_voxelize);
  const StageRun run = runStages(c, &voxelize);
  size_t occupied = 0;
  for (uint32_t w : run.buffers.at(BufferId::common_voxelize_weight_sum).words) occupied += w != 0u;
  writeVdb(out, buffersOf(run.buffers, voxelize, sums), run.scene.grid,
           {{"voxgi_mode", voxelizeModeName(run.settings.voxelizeMode)},
            {"voxgi_backend", run.backend.gpu ? run.backend.context->renderer() : "cpu"}});
  std::cout << "voxelized " << run.scene.triangleCount() << " triangles into "
            << run.scene.grid.resolution << "^3 (" << voxelizeModeName(run.settings.voxelizeMode)
            << ", " << run.backendName() << "): " << occupied << " occupied voxels in "
            << run.seconds << " s -> " << out << "\n";
  return kExitOk;
}

struct SampleOptions {
  std::string scene, out, gradient;
  int64_t points = 0;
  double noise = 0.0;
  uint64_t seed = 1;
};

// voxgi sample: a scene's meshes as a point-cloud PLY (common/surface_sampling.h).
int cmdSample(const SampleOptions& o) {
  checkOutputPath(o.out);
  SurfaceSampling sampling;
  sampling.points = size_t(o.points);
  sampling.noise = o.noise;
  sampling.seed = o.seed;
  if (!o.gradient.empty()) {  // "y:0.25"
    const size_t colon = o.gradient.find(':');
    const std::string axis = o.gradient.substr(0, colon);
    double ratio = 0.0;
    const std::string value = colon == std::string::npos ? "" : o.gradient.substr(colon + 1);
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), ratio);
    if (axis.size() != 1 || axis.find_first_of("xyz") != 0 || ec != std::errc() ||
        end != value.data() + value.size() || !(ratio > 0.0 && ratio <= 1e6))
      throw InputError("--density-gradient", "",
                       "expected AXIS:RATIO with AXIS x, y or z and RATIO in (0, 1e6], got '" +
                           o.gradient + "'");
    sampling.gradientAxis = axis[0] - 'x';
    sampling.gradientRatio = ratio;
  }
  // Positions, normals, colours and radii in memory (52 bytes) and the file (52 bytes).
  requireMemory(uint64_t(o.points) * 104u, "the sampled points", "--points", "");
  const Scene scene = loadScene(o.scene);
  const auto start = std::chrono::steady_clock::now();
  const PointCloud cloud = sampleSurfaces(scene, sampling);
  writePointCloudPly(cloud, o.out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "sampled " << cloud.size() << " points from " << scene.triangleCount()
            << " triangles in " << seconds << " s -> " << o.out << "\n";
  return kExitOk;
}

// The stages --stage names: every step of the technique for "all", else the one it resolves to.
std::vector<const StageSpec*> requestedStages(const Technique& technique,
                                              const std::string& stage) {
  if (stage == "all") return technique.steps();
  return {&resolveStage(technique, stage)};
}

int cmdDiff(const Common& c, const std::string& stage, const std::string& json,
            const std::string& dumpDir) {
  const Technique& technique = findTechnique(c.technique);
  Scene scene = loadWithOverrides(c);
  const Settings settings = makeSettings(c, scene, true);
  const std::vector<const StageSpec*> stages = requestedStages(technique, stage);
  if (!json.empty()) checkOutputPath(json);
  if (!dumpDir.empty()) prepareOutputFolder(dumpDir);
  auto context = gpu::GlContext::create(gpu::parseGlPlatform(c.gl));
  std::cerr << "voxgi: diff on " << context->renderer() << "\n";
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{technique, scene, settings, triangles};
  cpu::CpuBackend cpuBackend;
  gpu::GpuBackend gpuBackend(*context);
  const auto reports = validation::diffStages(ctx, cpuBackend, gpuBackend, stages, dumpDir);
  validation::printReport(std::cout, reports);
  if (!json.empty()) writeFileAtomically(json, validation::toJson(reports).dump(2) + "\n");
  bool pass = true;
  for (const auto& r : reports) pass &= r.pass;
  return pass ? kExitOk : kExitInternal;
}

int cmdPlan(const Common& c) {
  const Technique& technique = findTechnique(c.technique);
  const Scene scene = loadWithOverrides(c);
  const EffectPlan plan = technique.plan(scene, makeSettings(c, scene));
  std::cout << technique.name << " plan for " << scene.file << " (" << scene.grid.resolution
            << "^3 grid, " << scene.camera.width << "x" << scene.camera.height << " image):\n";
  for (const PlanItem& item : plan.items)
    std::cout << "  " << (item.in ? "in " : "out") << "  " << std::left << std::setw(20)
              << item.name << "  " << item.why << "\n";
  return kExitOk;
}

int cmdDump(const Common& c, const std::string& stage, const std::string& dir, bool checksums) {
  if (dir.empty() && !checksums)
    throw InputError("--out", "", "dump needs an output folder (--out) or --checksums");
  const Technique& technique = findTechnique(c.technique);
  const std::vector<const StageSpec*> requested = requestedStages(technique, stage);
  if (stage != "all") {
    // A stage the plan skips has no buffers: say so instead of writing another stage's.
    const Scene scene = loadWithOverrides(c);
    const EffectPlan plan = technique.plan(scene, makeSettings(c, scene, true));
    const StageSpec& s = *requested.front();
    if (!plan.runs(s.id))
      throw InputError("--stage", "",
                       "the plan skips " + s.qualifiedName() + " (" + plan.whySkipped(s.id) +
                           "), so it has no buffers to dump (voxgi plan shows why)");
  }
  if (!dir.empty()) prepareOutputFolder(dir);
  const StageRun run = runStages(c, stage == "all" ? nullptr : requested.front(), true);
  for (const StageSpec* s : run.stages) {
    if (stage != "all" && s != requested.front()) continue;
    if (checksums)
      for (const Buffer* b : buffersOf(run.buffers, *s, true))
        std::cout << "checksum " << b->spec->qualifiedName() << " " << b->words.size() << " "
                  << std::hex << std::setw(16) << std::setfill('0')
                  << fnv1a(b->words.data(), b->words.size() * sizeof(uint32_t)) << std::dec
                  << std::setfill(' ') << "\n";
    if (dir.empty()) continue;
    for (const std::string& path :
         writeBuffers(dir + "/" + std::string(s->name), buffersOf(run.buffers, *s, true),
                      run.scene.grid, {}, technique.sparseLayouts(run.buffers, run.scene.grid)))
      std::cout << "wrote " << path << "\n";
  }
  return kExitOk;
}

// voxgi ledger: a light propagation volume run up to propagate, with every step kept.
int cmdLedger(const Common& c, const std::string& json) {
  const Technique& technique = findTechnique(c.technique);
  const auto& steps = technique.steps();
  const StageSpec& propagate = stageSpec(StageId::lpv_propagate);
  if (std::find(steps.begin(), steps.end(), &propagate) == steps.end())
    throw InputError("--technique", "",
                     c.technique + " has no propagation volume; the ledger is lpv's and holpv's");
  if (!json.empty()) checkOutputPath(json);
  const StageRun run = runStages(c, &propagate, true);
  const VoxelTriangles triangles = prepareVoxelTriangles(run.scene, run.scene.grid);
  const StageContext ctx{technique, run.scene, run.settings, triangles};
  const validation::Ledger ledger = validation::lpvLedger(ctx, run.buffers);
  std::cout << technique.name << " ledger of " << run.scene.file << " ("
            << run.scene.grid.resolution << "^3, " << ledger.steps.size() << " steps, "
            << run.backendName() << ")\n";
  tools::printLedger(std::cout, ledger);
  if (!json.empty()) writeFileAtomically(json, tools::ledgerJson(ledger).dump(2) + "\n");
  return kExitOk;
}

// An image with a NaN or infinite pixel is not written: it would be garbage with exit 0. Input
// checks are meant to make this unreachable; if it happens, it is voxgi's bug (exit 1).
void requireFinite(const Image& image, const std::string& what) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec3 p = image.at(x, y);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw std::runtime_error(what + " has a non-finite pixel at (" + std::to_string(x) + ", " +
                                 std::to_string(y) + "); nothing written");
    }
}

// Every term file can be written before anything runs.
void checkTermOutputs(const std::string& out) {
  for (const LightTerm term : kLightTerms) checkOutputPath(termPath(out, term));
}

std::atomic<bool> interrupted{false};

// A technique of the registry: every stage it plans on the chosen backend, then its image.
int cmdRenderTechnique(const Common& c, const std::string& out, const std::string& png,
                       bool terms) {
  checkOutputPath(out);
  if (!png.empty()) checkOutputPath(png);
  if (terms) checkTermOutputs(out);
  const StageRun run = runStages(c, nullptr);
  const Technique& technique = findTechnique(c.technique);
  const Image image = bufferImage(run.buffers.at(technique.image));
  requireFinite(image, std::string(technique.name) + "'s image");
  std::optional<TermImages> split;
  if (terms) {
    split = techniqueTerms(technique, run.buffers, run.settings, run.scene);
    if (!split)
      throw InputError("--terms", "",
                       std::string(technique.name) + " has no per-term light buffers");
  }
  writeExr(out, image);
  if (split) writeTermImages(out, *split);
  if (!png.empty()) writePng(png, image);
  std::cout << technique.name << " rendered " << run.scene.camera.width << "x"
            << run.scene.camera.height << " at " << run.scene.grid.resolution << "^3 ("
            << run.backendName() << ") in " << run.seconds << " s -> " << out << "\n";
  return kExitOk;
}

// The reference path tracer (validation/reference/).
int cmdRenderPath(const Common& c, const reference::PathTraceOptions& base, const std::string& out,
                  const std::string& png, bool terms) {
  checkOutputPath(out);
  checkOutputPath(reference::variancePath(out));
  if (terms) checkTermOutputs(out);
  if (!png.empty()) checkOutputPath(png);
  const Scene scene = loadWithOverrides(c);
  reference::PathTraceOptions options = base;
  options.cancel = &interrupted;
  std::signal(SIGINT, [](int) { interrupted = true; });
  const bool tty = isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  std::mutex printing;
  auto lastPrint = start;
  if (tty)
    options.progress = [&](double fraction) {
      const std::lock_guard<std::mutex> lock(printing);
      const auto now = std::chrono::steady_clock::now();
      if (fraction < 1.0 && now - lastPrint < std::chrono::milliseconds(200)) return;
      lastPrint = now;
      const double elapsed = std::chrono::duration<double>(now - start).count();
      std::fprintf(stderr, "\rpath trace %5.1f%%  ETA %6.1f s ", 100.0 * fraction,
                   fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0);
    };
  reference::PathTraceResult result;
  try {
    result = reference::pathTrace(scene, options);
  } catch (const reference::Cancelled&) {
    std::cerr << (tty ? "\n" : "") << "voxgi: interrupted; nothing written\n";
    return 130;
  }
  if (tty) std::cerr << "\n";
  requireFinite(result.image, "the path-traced image");
  writeExr(out, result.image);
  writeExr(reference::variancePath(out), result.variance);
  if (terms) writeTermImages(out, result.terms);
  if (!png.empty()) writePng(png, result.image);
  std::cout << "path traced " << scene.camera.width << "x" << scene.camera.height << " at "
            << options.spp << " spp in " << result.seconds << " s ("
            << double(result.rays) / result.seconds / 1e6 << " M rays/s) -> " << out << " and "
            << reference::variancePath(out) << "\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"voxgi: real-time global illumination with a CPU reference and OpenGL shaders"};
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  Common c;
  auto addCommon = [&](CLI::App* cmd, bool backend) {
    cmd->add_option("scene", c.scene, "scene .json or mesh file (OBJ, glTF, PLY)")->required();
    // Given explicitly, 0 is an error, not "the scene's" (which is what leaving them out means).
    cmd->add_option("--resolution", c.resolution, "voxel grid resolution (power of two)")
        ->check(CLI::Range(1, kMaxResolution));
    cmd->add_option("--image", c.image, "image width in pixels (the height keeps the aspect)")
        ->check(CLI::Range(1, 16384));
    cmd->add_option("--mode", c.mode,
                    "voxelization: conservative or antialiased (default: voxelize.mode)")
        ->check(CLI::IsMember({"conservative", "antialiased"}));
    cmd->add_option("--gl", c.gl, "GL platform for the GPU backend")
        ->check(CLI::IsMember({"egl", "osmesa"}));
    if (backend)
      cmd->add_option("--backend", c.backend,
                      "cpu, gpu or auto (hardware GPU if present, else cpu)")
          ->check(CLI::IsMember({"cpu", "gpu", "auto"}));
    cmd->add_option("--threads", threads, "worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--preset", c.preset, "parameter preset of the technique (render --help)");
    cmd->add_option("--set", c.sets,
                    "technique parameter key=value (repeatable; see render --help)");
  };
  std::string out, stage = "all", json, dumpDir;
  bool sums = false;
  auto* voxelize = app.add_subcommand("voxelize", "voxelize a scene into an OpenVDB file");
  addCommon(voxelize, true);
  voxelize->add_option("--out", out, "output .vdb")->required();
  voxelize->add_flag("--sums", sums, "also write the fixed-point sums");
  const std::string techniqueHelp = "technique: " + techniqueNames();
  const auto addTechnique = [&](CLI::App* cmd) {
    cmd->add_option("--technique", c.technique, techniqueHelp)
        ->check(CLI::IsMember(techniqueList()));
  };
  const std::string stageHelp = "stage (vct/trace_cones, or trace_cones within --technique)";
  auto* diff = app.add_subcommand("diff", "run stages on both backends and compare every buffer");
  addCommon(diff, false);
  addTechnique(diff);
  diff->add_option("--stage", stage, stageHelp + " or all");
  diff->add_option("--json", json, "write the report as JSON");
  diff->add_option("--dump", dumpDir, "write cpu, gpu and difference grids (.vdb) here");
  auto* dump = app.add_subcommand("dump", "write every buffer of a stage (or all) as .vdb/.exr");
  addCommon(dump, true);
  addTechnique(dump);
  dump->add_option("--stage", stage, stageHelp + " or all")->required();
  dump->add_option("--out", out, "output folder");
  bool checksums = false;
  dump->add_flag("--checksums", checksums,
                 "print each buffer's word count and FNV-1a checksum (a run's fingerprint, to "
                 "check that a change or another machine reproduces it bit for bit)");
  auto* plan = app.add_subcommand(
      "plan",
      "print the stages and effects a technique's plan runs for a scene, and why each is "
      "in or out");
  addCommon(plan, false);
  addTechnique(plan);
  auto* render =
      app.add_subcommand("render", "render an image with a technique (" + techniqueNames() +
                                       ") or the reference path tracer (path)");
  addCommon(render, true);
  std::string png;
  reference::PathTraceOptions pathOptions;
  std::vector<std::string> renderTechniques = techniqueList();
  renderTechniques.push_back("path");
  render->add_option("--technique", c.technique, techniqueHelp + ", or path (the reference)")
      ->check(CLI::IsMember(renderTechniques));
  render->add_option("--spp", pathOptions.spp, "path: samples per pixel")
      ->check(CLI::Range(1, 1 << 20));
  render
      ->add_option("--bounces", pathOptions.bounces,
                   "path: indirect bounces after the first hit (-1: unlimited, Russian roulette)")
      ->check(CLI::Range(-1, 1000));
  render->add_option("--seed", pathOptions.seed, "path: random seed");
  render
      ->add_option("--sampler", pathOptions.sampler,
                   "path: sobol (Owen-scrambled Sobol', docs/path-tracer.md) or independent "
                   "(hashed random numbers)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, reference::SamplerKind>(std::begin(reference::kSamplerNames),
                                                        std::end(reference::kSamplerNames)),
          CLI::ignore_case));
  render
      ->add_option("--light-sampling", pathOptions.lightSampling,
                   "path: solid_angle (uniform in the solid angle an area light subtends, "
                   "docs/path-tracer.md) or area")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, reference::LightSampling>(
              std::begin(reference::kLightSamplingNames), std::end(reference::kLightSamplingNames)),
          CLI::ignore_case));
  render
      ->add_option("--replicas", pathOptions.replicas,
                   "path, sobol: independently scrambled replicas whose spread gives the variance "
                   "image (docs/path-tracer.md, \"Variance\")")
      ->check(CLI::Range(1, reference::kMaxReplicas));
  render->add_option("--out", out, "output EXR (linear); path also writes OUT.variance.exr")
      ->required();
  render->add_option("--png", png, "also write a tone-mapped sRGB preview");
  bool terms = false;
  render->add_flag("--terms", terms,
                   "also write the image's light terms as OUT.<term>.exr: emission, direct, "
                   "indirect_diffuse, indirect_specular (docs/accuracy.md, \"Error budget\")");
  std::string settingsHelp;
  for (const Technique& t : techniques()) settingsHelp += describeSettings(t);
  render->footer(settingsHelp);
  auto* ledger = app.add_subcommand(
      "ledger",
      "light propagation volumes: per step the flux sent, removed by the geometry volume, lost at "
      "the grid's border and read by shading, against the emitted flux");
  addCommon(ledger, true);
  ledger->add_option("--technique", c.technique, "lpv or holpv")
      ->check(CLI::IsMember(techniqueList()));
  ledger->add_option("--json", json, "also write the ledger as JSON");
  SampleOptions sample;
  auto* sampleCmd = app.add_subcommand(
      "sample", "a scene's meshes as a point-cloud PLY, with a scanner's noise and uneven density");
  sampleCmd->add_option("scene", sample.scene, "scene file or mesh file")->required();
  sampleCmd->add_option("--points", sample.points, "number of points")
      ->required()
      ->check(CLI::Range(int64_t(1), int64_t(1) << 32));
  sampleCmd
      ->add_option("--noise", sample.noise,
                   "standard deviation of an offset along the normal, scene units")
      ->check(CLI::Range(0.0, 1e15));
  sampleCmd->add_option("--density-gradient", sample.gradient,
                        "AXIS:RATIO, the density along x, y or z from 1 to RATIO (y:0.25)");
  sampleCmd->add_option("--seed", sample.seed, "random seed");
  sampleCmd->add_option("--out", sample.out, "output .ply")->required();
  tools::CompareOptions compare;
  auto* compareCmd = app.add_subcommand(
      "compare", "RMSE, relative MSE, MARE and SSIM of an image against a reference");
  tools::addCompareOptions(*compareCmd, compare);
  tools::StudyOptions study;
  auto* studyCmd = app.add_subcommand(
      "study", "sweep parameters, time each combination and plot its error against a reference");
  tools::addStudyOptions(*studyCmd, study);
  tools::BenchOptions bench;
  auto* benchCmd = app.add_subcommand("bench", "benchmarks (see docs/benchmarks.md)");
  auto* benchVoxelize =
      benchCmd->add_subcommand("voxelize", "voxelize: CPU 1/2 threads, GPU, OpenVDB meshToVolume");
  benchCmd->require_subcommand(1);
  tools::addBenchOptions(*benchVoxelize, bench);
  tools::BenchVctOptions benchVct;
  auto* benchVctCmd = benchCmd->add_subcommand(
      "vct", "every stage after voxelize: CPU per thread count, GPU (OSMesa); mip vs memcpy");
  tools::addBenchVctOptions(*benchVctCmd, benchVct);
  tools::BenchLpvOptions benchLpv;
  auto* benchLpvCmd = benchCmd->add_subcommand(
      "lpv",
      "lpv and holpv, every stage after voxelize: CPU per thread count, GPU (OSMesa); "
      "propagate vs memcpy");
  tools::addBenchLpvOptions(*benchLpvCmd, benchLpv);
  tools::BenchSvoOptions benchSvo;
  auto* benchSvoCmd = benchCmd->add_subcommand(
      "svo",
      "the octree's build from a 1.4M-point cloud: CPU per depth and thread count, "
      "OpenVDB's point rasterisation beside it");
  tools::addBenchSvoOptions(*benchSvoCmd, benchSvo);
  tools::BenchPathOptions benchPath;
  auto* benchPathCmd = benchCmd->add_subcommand(
      "path",
      "the path tracer per transport: each estimator's time and error against a converged "
      "render, efficiency 1 / (seconds x MSE)");
  tools::addBenchPathOptions(*benchPathCmd, benchPath);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help on a subcommand, --version
    std::cerr << "voxgi: " << printable(e.what()) << " (see voxgi --help)\n";
    return kExitBadInput;
  }
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  static_cast<size_t>(threads));
  try {
    if (*voxelize) return cmdVoxelize(c, out, sums);
    if (*render)
      return c.technique == "path" ? cmdRenderPath(c, pathOptions, out, png, terms)
                                   : cmdRenderTechnique(c, out, png, terms);
    if (*diff) return cmdDiff(c, stage, json, dumpDir);
    if (*dump) return cmdDump(c, stage, out, checksums);
    if (*plan) return cmdPlan(c);
    if (*ledger) return cmdLedger(c, json);
    if (*sampleCmd) return cmdSample(sample);
    if (*compareCmd) return tools::runCompare(compare);
    if (*studyCmd) return tools::runStudy(study);
    if (*benchVoxelize) return tools::runBenchVoxelize(bench);
    if (*benchVctCmd) return tools::runBenchVct(benchVct);
    if (*benchLpvCmd) return tools::runBenchLpv(benchLpv);
    if (*benchSvoCmd) return tools::runBenchSvo(benchSvo);
    if (*benchPathCmd) return tools::runBenchPath(benchPath);
  } catch (const InputError& e) {
    std::cerr << "voxgi: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user gave that the filesystem refuses (permissions, a full disk, a name too
    // long) where no check named it first: still one line naming the path.
    std::cerr << "voxgi: " << printable(e.path1().string()) << ": " << printable(e.code().message())
              << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    // The memory checks before each large allocation (common/memory.h) name the field to lower;
    // this is an allocation they did not foresee.
    std::cerr << "voxgi: out of memory (an allocation failed past voxgi's memory checks)\n";
    return kExitInternal;
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxgi: no OpenGL 4.5 context: " << printable(e.what())
              << " (use --backend cpu or auto)\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "voxgi: internal error: " << printable(e.what()) << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}
