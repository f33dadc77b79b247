// Scenes, plans, stage runs, diffs, checks against the oracle, the path tracer and image metrics
// for Python. Each releases the GIL while voxgi computes (so Python threads run stages side by
// side) and runs on `threads` worker threads of its own (a TBB arena: other calls keep theirs).
#include <chrono>
#include <optional>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>
#include <tbb/task_arena.h>

#include "common/error.h"
#include "common/io/buffer_io.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/settings.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tools/backend.h"
#include "tools/command.h"
#include "tools/metrics_json.h"
#include "tools/python/arrays.h"
#include "tools/python/bindings.h"
#include "validation/check.h"
#include "validation/reference/path_trace.h"
#include "validation/report.h"

namespace voxgi::python {
namespace {

using ScenePtr = std::shared_ptr<Scene>;

// A run's stages and what they wrote; its arrays are views of `buffers`.
struct Run {
  ScenePtr scene;
  std::string technique;
  Settings settings;
  VoxelTriangles triangles;
  BufferSet buffers;
  std::vector<std::string> stages;  // those the plan ran, in order
  double seconds = 0.0;
  std::string backend;  // "cpu", "gpu: <renderer>"
  std::string note;     // why backend="auto" chose the CPU
};

// The options every scene-taking call shares, as the CLI's --technique, --preset and --set.
struct Choice {
  const Technique& technique;
  Settings settings;
};

Choice choose(const Scene& scene, const std::string& technique, const std::string& preset,
              const std::vector<std::string>& sets, bool inspect = false) {
  const Technique& t = findTechnique(technique, "technique");
  Settings s = resolveSettings(t, scene.settings, scene.file, preset, sets);
  s.inspect = inspect;
  return {t, s};
}

void checkThreads(int threads) {
  if (threads < 0 || threads > 1024)
    throw InputError("threads", "",
                     "must be in [1, 1024] (0 or None: all cores), got " + std::to_string(threads));
}

// Runs f on `threads` workers (0: TBB's default arena, every core).
template <class F>
void withThreads(int threads, F&& f) {
  checkThreads(threads);
  if (threads == 0) return f();
  tbb::task_arena arena(threads);
  arena.execute(f);
}

py::object fromJson(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

const BufferSpec& bufferNamed(const std::string& name) {
  std::string known;
  for (const BufferSpec& b : bufferSpecs()) {
    if (b.qualifiedName() == name) return b;
  }
  throw InputError("buffer", name,
                   "no such buffer (voxgi.buffers() lists them, e.g. vct/light_voxels.radiance)");
}

// Given explicitly, 0 is an error, not "the scene's" (which is what None means), as on the CLI.
ScenePtr loadScenePy(const std::string& source, const std::optional<std::string>& text,
                     const std::string& camera, std::optional<int> resolution,
                     std::optional<int> image) {
  py::gil_scoped_release release;
  Scene s = text ? loadSceneText(*text, source, {.camera = camera})
                 : loadScene(source, {.camera = camera});
  if (resolution) {
    s.grid.resolution = readResolution("resolution", "", *resolution);
    checkGrid(s, "resolution " + std::to_string(*resolution));
  }
  if (image) setImageWidth(s, *image, "image");
  return std::make_shared<Scene>(std::move(s));
}

py::dict planDict(const ScenePtr& scene, const std::string& technique, const std::string& preset,
                  const std::vector<std::string>& sets) {
  const Choice c = choose(*scene, technique, preset, sets);
  const VoxelTriangles none;
  const StageContext ctx{c.technique, *scene, c.settings, none};
  py::list items, stages;
  for (const PlanItem& item : ctx.plan.items) {
    py::dict d;
    d["name"] = item.name;
    d["in"] = item.in;
    d["why"] = item.why;
    items.append(d);
  }
  for (const StageSpec* s : plannedStages(ctx)) stages.append(s->qualifiedName());
  py::dict out;
  out["technique"] = std::string(c.technique.name);
  out["items"] = items;
  out["stages"] = stages;
  out["settings"] = settingValues(c.settings, c.technique);
  return out;
}

std::shared_ptr<Run> runPy(const ScenePtr& scene, const std::string& technique,
                           const std::string& stage, const std::string& backend,
                           const std::string& gl, const std::string& preset,
                           const std::vector<std::string>& sets, int threads, bool inspect) {
  if (backend != "cpu" && backend != "gpu" && backend != "auto")
    throw InputError("backend", "", "must be cpu, gpu or auto, got \"" + backend + "\"");
  const gpu::GlPlatform platform = gpu::parseGlPlatform(gl);
  const Choice c = choose(*scene, technique, preset, sets, inspect);
  const StageSpec* last = stage.empty() ? nullptr : &resolveStage(c.technique, stage, "stage");
  auto run = std::make_shared<Run>();
  run->scene = scene;
  run->technique = std::string(c.technique.name);
  run->settings = c.settings;
  py::gil_scoped_release release;
  withThreads(threads, [&] {
    // The GL context lives on this thread for this call only: a run's buffers are host memory.
    tools::BackendChoice chosen = tools::chooseBackend(backend, platform);
    run->backend = chosen.gpu ? "gpu: " + chosen.context->renderer() : "cpu";
    run->note = chosen.note;
    const auto start = std::chrono::steady_clock::now();
    run->triangles = prepareVoxelTriangles(*scene, scene->grid);
    const StageContext ctx{c.technique, *scene, run->settings, run->triangles};
    runPipeline(chosen.stages(), ctx, run->buffers, last,
                [&](const StageSpec& s, double) { run->stages.push_back(s.qualifiedName()); });
    run->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  return run;
}

// The run's buffers as `voxgi dump` writes them: <out>/<stage>.vdb and <out>/<stage>.<buffer>.exr
// per stage it ran (or the one named).
std::vector<std::string> dumpRun(const Run& r, const std::string& out, const std::string& stage) {
  const Technique& t = findTechnique(r.technique);
  const StageSpec* only = stage.empty() ? nullptr : &resolveStage(t, stage, "stage");
  if (only != nullptr &&
      std::find(r.stages.begin(), r.stages.end(), only->qualifiedName()) == r.stages.end())
    throw InputError("stage", only->qualifiedName(), "the run did not run it (Run.stages)");
  py::gil_scoped_release release;
  prepareOutputFolder(out);
  std::vector<std::string> paths;
  const SparseLayouts layouts = t.sparseLayouts(r.buffers, r.scene->grid);
  for (const std::string& name : r.stages) {
    const StageSpec& s = resolveStage(t, name, "stage");
    if (only != nullptr && &s != only) continue;
    for (const std::string& path :
         writeBuffers(out + "/" + std::string(s.name), tools::buffersOf(r.buffers, s, true),
                      r.scene->grid, {}, layouts))
      paths.push_back(path);
  }
  return paths;
}

py::object diffPy(const ScenePtr& scene, const std::string& technique, const std::string& stage,
                  const std::string& gl, const std::string& preset,
                  const std::vector<std::string>& sets, int threads) {
  const gpu::GlPlatform platform = gpu::parseGlPlatform(gl);
  const Choice c = choose(*scene, technique, preset, sets, true);
  const std::vector<const StageSpec*> stages =
      stage == "all" ? c.technique.steps()
                     : std::vector<const StageSpec*>{&resolveStage(c.technique, stage, "stage")};
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    withThreads(threads, [&] {
      auto context = gpu::GlContext::create(platform);
      cpu::CpuBackend cpuBackend;
      gpu::GpuBackend gpuBackend(*context);
      const VoxelTriangles triangles = prepareVoxelTriangles(*scene, scene->grid);
      const StageContext ctx{c.technique, *scene, c.settings, triangles};
      report = validation::toJson(validation::diffStages(ctx, cpuBackend, gpuBackend, stages, ""));
    });
  }
  return fromJson(report);
}

py::object checkPy(const ScenePtr& scene, const std::string& technique, const std::string& preset,
                   const std::vector<std::string>& sets, int threads, const py::dict& arrays) {
  if (arrays.empty()) throw InputError("check", "", "no buffers to check");
  std::vector<std::pair<const BufferSpec*, py::array>> given;
  for (const auto& [name, array] : arrays)
    given.emplace_back(&bufferNamed(py::cast<std::string>(name)), py::array::ensure(array));
  for (const auto& [spec, array] : given)
    if (!array) throw InputError("check", spec->qualifiedName(), "not an array");
  const Choice c = choose(*scene, technique, preset, sets, true);
  const StageSpec& stage =
      resolveStage(c.technique, given.front().first->stageSpec().qualifiedName(), "check");
  BufferSet candidate;
  for (const auto& [spec, array] : given) candidate.put(Buffer(*spec, glm::ivec3(0)));
  validation::candidateStage(candidate, "check");  // one stage's buffers
  VoxelTriangles triangles;
  {
    py::gil_scoped_release release;
    triangles = prepareVoxelTriangles(*scene, scene->grid);
  }
  const StageContext ctx{c.technique, *scene, c.settings, triangles};
  validation::requireOracle(ctx, stage);
  BufferSet oracle;
  {
    py::gil_scoped_release release;
    withThreads(threads, [&] {
      cpu::CpuBackend cpuBackend;
      runPipeline(cpuBackend, ctx, oracle, &stage);
    });
  }
  candidate = {};
  for (const auto& [spec, array] : given) {
    const Buffer* own = oracle.find(spec->id);
    if (own == nullptr)
      throw InputError("check", spec->qualifiedName(),
                       "the plan does not produce this buffer for this scene (it needs " +
                           std::string(effectSpec(spec->need).name) + "): voxgi.plan() says why");
    candidate.put(arrayBuffer(*spec, own->extent, array, "check"));
  }
  nlohmann::json report;
  {
    py::gil_scoped_release release;
    report = validation::toJson({validation::checkStage(ctx, oracle, candidate)});
  }
  return fromJson(report);
}

py::dict pathTracePy(const ScenePtr& scene, int spp, uint64_t seed, int bounces, int replicas,
                     const std::string& sampler, int threads) {
  const reference::PathTraceOptions o = pathOptions(spp, seed, bounces, replicas, sampler);
  reference::PathTraceResult r;
  {
    py::gil_scoped_release release;
    withThreads(threads, [&] { r = reference::pathTrace(*scene, o); });
  }
  py::dict out;
  out["image"] = imageArray(std::move(r.image));
  out["variance"] = imageArray(std::move(r.variance));
  out["rays"] = r.rays;
  out["seconds"] = r.seconds;
  return out;
}

py::object comparePy(const py::array& testArray, const py::array& referenceArray,
                     const std::optional<py::array>& maskArray, const std::string& units) {
  const Image test = arrayImage(testArray, "test");
  const Image ref = arrayImage(referenceArray, "reference");
  if (test.width != ref.width || test.height != ref.height)
    throw InputError("test", "",
                     "the images differ in size: " + std::to_string(test.width) + "x" +
                         std::to_string(test.height) + " against the reference's " +
                         std::to_string(ref.width) + "x" + std::to_string(ref.height));
  std::vector<uint8_t> mask;
  if (maskArray) {
    const auto m = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(*maskArray);
    if (!m || m.ndim() != 2 || m.shape(0) != ref.height || m.shape(1) != ref.width)
      throw InputError("mask", "", "must be a (height, width) array of the reference's size");
    mask.assign(m.data(), m.data() + m.size());
    if (std::find(mask.begin(), mask.end(), 1) == mask.end())
      throw InputError("mask", "", "keeps no pixel");
  }
  std::optional<reference::MetricUnits> u;
  for (const auto& [name, value] : reference::kMetricUnitsNames)
    if (units == name) u = value;
  if (!u) throw InputError("units", "", "must be mean or absolute, got \"" + units + "\"");
  const reference::MetricScale scale = reference::metricScale(ref, mask, *u);
  const reference::ImageMetrics m = reference::compareImages(test, ref, mask, scale);
  const reference::Baselines baselines = reference::trivialBaselines(ref, mask, scale);
  nlohmann::json out = tools::metricsJson(m);
  out["pixels"] = m.pixels;
  out["units"] = units;
  out["unit"] = {scale.unit.r, scale.unit.g, scale.unit.b};
  out["baselines"] = {{"black", tools::metricsJson(baselines.black)},
                      {"constant", tools::metricsJson(baselines.constant)}};
  return fromJson(out);
}

}  // namespace

reference::PathTraceOptions pathOptions(int spp, uint64_t seed, int bounces, int replicas,
                                        const std::string& sampler) {
  if (spp < 1 || spp > (1 << 20))  // voxgi render --spp's range
    throw InputError("spp", "", "must be in [1, 1048576], got " + std::to_string(spp));
  if (bounces < -1 || bounces > 1024)
    throw InputError("bounces", "",
                     "must be in [-1, 1024] (-1: unlimited), got " + std::to_string(bounces));
  if (replicas < 1 || replicas > reference::kMaxReplicas)
    throw InputError("replicas", "", "must be in [1, 64], got " + std::to_string(replicas));
  reference::PathTraceOptions o;
  o.spp = spp;
  o.seed = seed;
  o.bounces = bounces;
  o.replicas = replicas;
  bool known = false;
  for (const auto& [name, kind] : reference::kSamplerNames)
    if (sampler == name) o.sampler = kind, known = true;
  if (!known)
    throw InputError("sampler", "", "must be sobol or independent, got \"" + sampler + "\"");
  return o;
}

void bindRuns(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(
      m, "Scene", "A loaded scene (voxgi.load_scene): its meshes, lights, camera and grid.")
      .def_property_readonly(
          "file", [](const Scene& s) { return s.file; }, "the scene file it was loaded from")
      .def_property_readonly(
          "resolution", [](const Scene& s) { return s.grid.resolution; },
          "the voxel grid's resolution N (an N^3 grid)")
      .def_property_readonly(
          "grid_min",
          [](const Scene& s) {
            return std::vector<double>{s.grid.min.x, s.grid.min.y, s.grid.min.z};
          },
          "the grid's lowest corner in world space")
      .def_property_readonly(
          "grid_size", [](const Scene& s) { return s.grid.size; },
          "the grid's edge length in world units")
      .def_property_readonly(
          "image", [](const Scene& s) { return std::pair(s.camera.width, s.camera.height); },
          "(width, height) of its images")
      .def_property_readonly(
          "triangles", [](const Scene& s) { return s.triangleCount(); }, "its triangles")
      .def_property_readonly(
          "lights", [](const Scene& s) { return s.lights.size(); },
          "its lights (point, spot, directional)")
      .def("__repr__", [](const Scene& s) {
        return "<voxgi.Scene " + s.file + ": " + std::to_string(s.triangleCount()) +
               " triangles, " + std::to_string(s.grid.resolution) + "^3 grid, " +
               std::to_string(s.camera.width) + "x" + std::to_string(s.camera.height) + " image>";
      });
  py::class_<Run, std::shared_ptr<Run>>(
      m, "Run",
      "The stages a voxgi.run ran and the buffers they wrote; run[name] is one as a read-only "
      "NumPy view (docs/python.md, \"Arrays\").")
      .def_property_readonly(
          "technique", [](const Run& r) { return r.technique; }, "the technique that ran")
      .def_property_readonly(
          "backend", [](const Run& r) { return r.backend; }, "cpu, or gpu: <renderer>")
      .def_property_readonly(
          "note", [](const Run& r) { return r.note; },
          "why backend=auto chose the CPU (empty otherwise)")
      .def_property_readonly(
          "stages", [](const Run& r) { return r.stages; }, "the stages the plan ran, in order")
      .def_property_readonly(
          "seconds", [](const Run& r) { return r.seconds; },
          "the seconds the stages took, all together")
      .def_property_readonly(
          "settings",
          [](const Run& r) { return settingValues(r.settings, findTechnique(r.technique)); },
          "every setting's value, key=value")
      .def_property_readonly(
          "names",
          [](const Run& r) {
            std::vector<std::string> names;
            for (const auto& [id, b] : r.buffers) names.push_back(b.spec->qualifiedName());
            return names;
          },
          "the buffers the run holds, by name")
      .def(
          "array",
          [](py::object self, const std::string& name) {
            const Run& r = self.cast<const Run&>();
            const Buffer* b = r.buffers.find(bufferNamed(name).id);
            if (b == nullptr)
              throw py::key_error(name + ": not in this run (Run.names lists what it holds)");
            return bufferArray(*b, self);
          },
          py::arg("name"), "The buffer `name` as a read-only NumPy view (run[name] is the same).")
      .def("dump", &dumpRun, py::arg("out"), py::arg("stage") = "",
           "Writes the run's buffers (of `stage` alone when given) to the folder `out` as voxgi "
           "dump does; returns the paths.");
  m.def("load_scene", &loadScenePy, py::arg("source"), py::arg("text"), py::arg("camera"),
        py::arg("resolution"), py::arg("image"));
  m.def("plan", &planDict, py::arg("scene"), py::arg("technique"), py::arg("preset"),
        py::arg("settings"));
  m.def("run", &runPy, py::arg("scene"), py::arg("technique"), py::arg("stage"), py::arg("backend"),
        py::arg("gl"), py::arg("preset"), py::arg("settings"), py::arg("threads"),
        py::arg("inspect"));
  m.def("diff", &diffPy, py::arg("scene"), py::arg("technique"), py::arg("stage"), py::arg("gl"),
        py::arg("preset"), py::arg("settings"), py::arg("threads"));
  m.def("check", &checkPy, py::arg("scene"), py::arg("technique"), py::arg("preset"),
        py::arg("settings"), py::arg("threads"), py::arg("arrays"));
  m.def("path_trace", &pathTracePy, py::arg("scene"), py::arg("spp"), py::arg("seed"),
        py::arg("bounces"), py::arg("replicas"), py::arg("sampler"), py::arg("threads"));
  m.def("compare", &comparePy, py::arg("test"), py::arg("reference"), py::arg("mask"),
        py::arg("units"));
}

}  // namespace voxgi::python
