#include "tools/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "common/io/buffer_io.h"
#include "common/error.h"
#include "common/io/term_images.h"
#include "common/light_terms.h"
#include "common/io/output_file.h"
#include "common/pipeline.h"
#include "common/scene_io/scene_load.h"
#include "common/settings.h"
#include "common/settings_table.h"
#include "common/technique.h"
#include "common/voxel_triangles.h"
#include "tools/bench.h"
#include "tools/compare.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/pareto.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "validation/reference/path_trace.h"
#include "tools/command.h"
#include "tools/metrics_json.h"
#include "tools/plot_script.h"

namespace voxgi::tools {

extern const char* const kPlotStudyScript;  // tools/plot_study.py, embedded by CMake

namespace {

// Keys only the path tracer takes; every other key is a staged technique's (a --set key,
// `resolution` or `backend`).
const std::set<std::string> kPathKeys{"spp",     "bounces",        "seed",
                                      "sampler", "light_sampling", "replicas"};

// A path key to the path tracer; to a staged technique `resolution`, `backend`, a shared key or
// one of its own (a sweep of propagate.steps leaves vct alone).
bool appliesTo(const std::string& key, const std::string& technique) {
  if (technique == "path") return kPathKeys.count(key) != 0;
  if (kPathKeys.count(key) != 0) return false;
  if (key == "resolution" || key == "backend") return true;
  for (const Param& p : sharedParams())
    if (p.key == key) return true;
  for (const Param& p : findTechnique(technique).params())
    if (p.key == key) return true;
  return false;
}

struct Sweep {
  std::string key;
  std::vector<std::string> values;
};

Sweep parseSweep(const std::string& text) {
  const size_t eq = text.find('=');
  Sweep s{text.substr(0, eq), {}};
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError("--sweep", "", "expected key=v1,v2,... got '" + text + "'");
  std::istringstream values(text.substr(eq + 1));
  for (std::string v; std::getline(values, v, ',');)
    if (!v.empty()) s.values.push_back(v);
  return s;
}

int parseInt(const std::string& key, const std::string& value) {
  size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || value.empty())
    throw InputError("--sweep", key, "expected an integer, got '" + value + "'");
  return n;
}

// The value that `names` gives `name`, for a --sweep of `key`.
template <class T, size_t N>
T named(const std::pair<const char*, T> (&names)[N], const std::string& key,
        const std::string& name) {
  std::string known;
  for (const auto& [n, value] : names) {
    if (name == n) return value;
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  throw InputError("--sweep", key, "expected one of " + known + ", got '" + name + "'");
}

// One point of the study, checked and ready to run.
struct Job {
  std::string technique;
  std::vector<std::pair<std::string, std::string>> values;  // the swept key = value
  Scene scene;
  Settings settings;                    // a staged technique
  bool gpu = false;                     // a staged technique
  reference::PathTraceOptions options;  // path
  // "resolution=64 step=0.5": each key's last dot-separated part.
  std::string label() const {
    std::ostringstream out;
    for (const auto& [key, value] : values)
      out << (out.tellp() == 0 ? "" : " ") << key.substr(key.rfind('.') + 1) << "=" << value;
    return values.empty() ? technique : out.str();
  }
};

struct Result {
  double seconds = 0.0;
  std::map<std::string, double> stages;  // stage -> median seconds
  Image image;
  std::optional<TermImages> terms;  // the image's light terms
};

// A technique of the registry through the stage runner, timing each stage.
Result runTechnique(const Job& job, int repeats, gpu::GlContext* context) {
  const Technique& technique = findTechnique(job.technique);
  const VoxelTriangles triangles = prepareVoxelTriangles(job.scene, job.scene.grid);
  const StageContext ctx{technique, job.scene, job.settings, triangles};
  cpu::CpuBackend cpuBackend;
  std::unique_ptr<gpu::GpuBackend> gpuBackend;
  if (job.gpu) gpuBackend = std::make_unique<gpu::GpuBackend>(*context);
  StageBackend& backend = job.gpu ? static_cast<StageBackend&>(*gpuBackend) : cpuBackend;
  std::map<std::string, std::vector<double>> stageTimes;
  std::vector<double> totals;
  Result r;
  for (int k = 0; k < repeats; ++k) {
    BufferSet buffers;
    double total = 0.0;
    runPipeline(backend, ctx, buffers, nullptr, [&](const StageSpec& stage, double seconds) {
      stageTimes[stage.qualifiedName()].push_back(seconds);
      total += seconds;
    });
    totals.push_back(total);
    if (k + 1 == repeats) {
      r.image = bufferImage(buffers.at(technique.image));
      r.terms = techniqueTerms(technique, buffers, job.settings, job.scene);
    }
  }
  for (const auto& [stage, times] : stageTimes) r.stages[stage] = median(times);
  r.seconds = median(totals);
  return r;
}

Result runPath(const Job& job, int repeats) {
  std::vector<double> times;
  Result r;
  for (int k = 0; k < repeats; ++k) {
    reference::PathTraceResult p = reference::pathTrace(job.scene, job.options);
    times.push_back(p.seconds);
    r.image = std::move(p.image);
    r.terms = std::move(p.terms);
  }
  r.seconds = median(times);
  r.stages["path_trace"] = r.seconds;
  return r;
}

// Every combination of the sweeps that apply to each technique, checked before anything runs.
std::vector<Job> makeJobs(const StudyOptions& o, const std::vector<Sweep>& sweeps) {
  std::vector<Job> jobs;
  for (const Sweep& s : sweeps) {
    bool used = false;
    for (const std::string& technique : o.techniques) used |= appliesTo(s.key, technique);
    if (!used)
      throw InputError("--sweep", s.key,
                       "is a parameter of none of the techniques studied (voxgi render --help "
                       "lists them)");
  }
  const Scene scene = loadStudyScene(o);  // each job changes its own copy
  for (const std::string& technique : o.techniques) {
    std::vector<const Sweep*> mine;
    for (const Sweep& s : sweeps)
      if (appliesTo(s.key, technique)) mine.push_back(&s);
    size_t count = 1;
    for (const Sweep* s : mine) count *= s->values.size();
    if (count > 10000) throw InputError("--sweep", "", "more than 10000 combinations");
    for (size_t index = 0; index < count; ++index) {
      Job job;
      job.technique = technique;
      job.scene = scene;
      if (technique != "path")
        job.settings = resolveSettings(findTechnique(technique), job.scene.settings, job.scene.file,
                                       o.preset, o.sets);
      size_t rest = index;
      for (const Sweep* s : mine) {
        const std::string& value = s->values[rest % s->values.size()];
        rest /= s->values.size();
        job.values.emplace_back(s->key, value);
        if (s->key == "resolution") {
          job.scene.grid.resolution =
              readResolution("--sweep", "resolution", parseInt(s->key, value));
          checkGrid(job.scene, "--sweep resolution=" + value);
        } else if (s->key == "backend") {
          if (value != "cpu" && value != "gpu")
            throw InputError("--sweep", "backend", "expected cpu or gpu, got '" + value + "'");
          job.gpu = value == "gpu";
        } else if (s->key == "spp")
          job.options.spp = std::clamp(parseInt(s->key, value), 1, 1 << 20);
        else if (s->key == "bounces")
          job.options.bounces = std::max(parseInt(s->key, value), -1);
        else if (s->key == "seed")
          job.options.seed = uint64_t(parseInt(s->key, value));
        else if (s->key == "sampler")
          job.options.sampler = named(reference::kSamplerNames, s->key, value);
        else if (s->key == "light_sampling")
          job.options.lightSampling = named(reference::kLightSamplingNames, s->key, value);
        else if (s->key == "replicas")
          job.options.replicas = std::clamp(parseInt(s->key, value), 1, reference::kMaxReplicas);
        else
          applySetting(job.settings, s->key + "=" + value, "--sweep");
      }
      jobs.push_back(std::move(job));
    }
  }
  for (const Sweep& s : sweeps) {
    bool used = false;
    for (const std::string& t : o.techniques) used |= appliesTo(s.key, t);
    if (!used) throw InputError("--sweep", s.key, "applies to none of the techniques studied");
  }
  return jobs;
}

// The plot of error against time (tools/plot_study.py).
void plot(const std::string& csv, const std::string& png, const std::string& metric,
          const std::string& title, const std::string& noiseFloor) {
  std::vector<std::string> args{metric, metricLabel(metric), title};
  if (!noiseFloor.empty()) args.push_back(noiseFloor);
  runPlotScript(kPlotStudyScript, csv, png, args);
}

// The error columns of a CSV row: rmse, rel_mse, mare, ssim, ssim_loss.
std::string errorCells(const reference::ImageMetrics& m) {
  std::ostringstream out;
  out.precision(6);
  out << m.rmse << "," << m.relMse << "," << m.mare << "," << m.ssim << "," << 1.0 - m.ssim;
  return out.str();
}

// The error columns, then energy_r, energy_g, energy_b (empty where undefined).
std::string metricCells(const reference::ImageMetrics& m) {
  std::ostringstream out;
  out.precision(6);
  out << errorCells(m);
  for (int c = 0; c < 3; ++c) {
    out << ",";
    if (!std::isnan(m.energy[c])) out << m.energy[c];
  }
  return out.str();
}

}  // namespace

void addStudyOptions(CLI::App& cmd, StudyOptions& o) {
  cmd.add_option("scene", o.scene, "scene .json or mesh file")->required();
  std::vector<std::string> names{"path"};
  for (const Technique& t : techniques()) names.emplace_back(t.name);
  cmd.add_option("--technique", o.techniques, techniqueNames() + " and/or path (comma-separated)")
      ->delimiter(',')
      ->check(CLI::IsMember(names));
  cmd.add_option(
      "--sweep", o.sweeps,
      "key=v1,v2,... (repeatable): a --set key, resolution or backend (staged techniques); spp, "
      "bounces, seed, sampler, light_sampling or replicas (path)");
  cmd.add_option("--preset", o.preset, "parameter preset, before --set and the sweeps");
  cmd.add_option("--set", o.sets, "fixed parameter key=value (repeatable)");
  cmd.add_option("--reference", o.reference, "reference image (.exr)")->required();
  cmd.add_option("--mask", o.mask, "only pixels non-zero in this image count");
  cmd.add_option("--csv", o.csv, "output CSV, one row per combination")->required();
  cmd.add_option("--plot", o.plot, "output PNG: error against time, Pareto front marked");
  cmd.add_option("--metric", o.metric, "error for the Pareto front and the plot")
      ->check(CLI::IsMember({"rmse", "rel_mse", "mare", "ssim_loss"}));
  cmd.add_option("--image", o.image, "image width in pixels (the height keeps the aspect)");
  cmd.add_option("--resolution", o.resolution,
                 "voxel grid resolution (power of two) before the sweeps; default the scene's");
  cmd.add_option("--repeat", o.repeats, "runs per combination; times are medians")
      ->check(CLI::Range(1, 100));
  cmd.add_flag("--terms", o.terms,
               "also measure each light term against REFERENCE.<term>.exr (voxgi render --terms "
               "writes them): relMSE, share of the image's relMSE and brightness per term");
  cmd.add_option("--gl", o.gl, "GL platform for backend=gpu")
      ->check(CLI::IsMember({"egl", "osmesa"}));
  addUnitsOptions(cmd, o.units, o.skipEmitters);
  cmd.add_option("--shard", o.shard,
                 "I/N: run the jobs k with k % N == I only and write their records to "
                 "CSV.shard-I-of-N.json, for a batch scheduler's job array (docs/accuracy.md, "
                 "\"Studies on a cluster\")");
  cmd.add_option("--merge", o.merge,
                 "N: write the CSV (and plot) from the records of shards 0..N-1, as one run "
                 "writes them")
      ->check(CLI::Range(1, 10000));
  cmd.add_option("--frames", o.frames,
                 "study frames A to B (A:B or A:B:STEP) of an animated scene on the CPU: per-frame "
                 "error, flicker and cost (updated and rebuilt); --reference then holds a frame "
                 "field, REF_%04d.exr (docs/motion.md)");
  cmd.add_option("--fps", o.fps, "frames per second of --frames")->check(CLI::Range(1e-3, 1e6));
}

namespace {

// The reference a study measures against: its image, the pixels that count, the metrics' scale
// and its light terms (with --terms).
struct StudyReference {
  Image image;
  std::vector<uint8_t> mask;
  reference::MetricScale scale;
  std::optional<TermImages> terms;
};

StudyReference readStudyReference(const StudyOptions& o) {
  StudyReference r;
  r.image = readReference(o.reference);
  r.mask = withoutEmitters(o.skipEmitters, o.reference, r.image, readMask(o.mask, r.image));
  r.scale = reference::metricScale(r.image, r.mask, o.units);
  if (o.terms) {
    r.terms = readTermImages(o.reference);
    for (const LightTerm term : kLightTerms)
      checkSameSize(termImage(*r.terms, term).width, termImage(*r.terms, term).height,
                    termPath(o.reference, term), r.image);
  }
  return r;
}

// One combination's run and its errors against the reference.
struct Measured {
  Result result;
  reference::ImageMetrics metrics;
  // Its image without the indirect terms (nullopt for a technique without terms).
  std::optional<reference::ImageMetrics> directOnly;
  // Per term (empty without --terms or for a technique without terms).
  std::vector<reference::TermMetrics> terms;
};

Measured measure(const Job& job, const StudyOptions& o, const StudyReference& ref,
                 std::unique_ptr<gpu::GlContext>& context) {
  if (job.gpu && context == nullptr) context = gpu::GlContext::create(gpu::parseGlPlatform(o.gl));
  Measured m;
  m.result = job.technique == "path" ? runPath(job, o.repeats)
                                     : runTechnique(job, o.repeats, context.get());
  m.metrics = reference::compareImages(m.result.image, ref.image, ref.mask, ref.scale);
  if (m.result.terms)
    m.directOnly =
        reference::compareImages(directOnly(*m.result.terms), ref.image, ref.mask, ref.scale);
  if (ref.terms && m.result.terms)
    for (const LightTerm term : kLightTerms)
      m.terms.push_back(reference::compareTerm(termImage(*m.result.terms, term),
                                               termImage(*ref.terms, term), ref.image, ref.mask,
                                               ref.scale));
  return m;
}

// The overall Pareto front of time against the --metric error, and each technique's own (its best
// trade-offs even where another wins).
struct Fronts {
  std::vector<bool> all, ownTechnique;
};

Fronts paretoFronts(const StudyOptions& o, const std::vector<Job>& jobs,
                    const std::vector<Measured>& measured) {
  std::vector<double> seconds, errors;
  for (const Measured& m : measured) {
    seconds.push_back(m.result.seconds);
    errors.push_back(metricError(m.metrics, o.metric));
  }
  Fronts fronts{reference::paretoFront(seconds, errors), std::vector<bool>(jobs.size(), false)};
  for (const std::string& technique : o.techniques) {
    std::vector<size_t> mine;
    std::vector<double> s, e;
    for (size_t k = 0; k < jobs.size(); ++k)
      if (jobs[k].technique == technique) {
        mine.push_back(k);
        s.push_back(seconds[k]);
        e.push_back(errors[k]);
      }
    const std::vector<bool> f = reference::paretoFront(s, e);
    for (size_t i = 0; i < mine.size(); ++i) fronts.ownTechnique[mine[i]] = f[i];
  }
  return fronts;
}

// The time columns: every stage of the studied techniques, then the path tracer.
std::vector<std::string> stageColumns(const StudyOptions& o) {
  std::vector<std::string> stages;
  for (const std::string& t : o.techniques)
    if (t != "path")
      for (const StageSpec* s : findTechnique(t).steps())
        if (std::find(stages.begin(), stages.end(), s->qualifiedName()) == stages.end())
          stages.push_back(s->qualifiedName());
  stages.emplace_back("path_trace");
  return stages;
}

void csvHeader(std::ostream& csv, const std::vector<Sweep>& sweeps,
               const std::vector<std::string>& stages, bool terms) {
  csv << "technique";
  for (const Sweep& s : sweeps) csv << "," << s.key;
  csv << ",label,seconds";
  for (const std::string& s : stages) csv << "," << s << "_seconds";
  csv << ",rmse,rel_mse,mare,ssim,ssim_loss,energy_r,energy_g,energy_b,direct_only_rmse,"
         "direct_only_rel_mse,direct_only_mare,direct_only_ssim,direct_only_ssim_loss,efficiency,"
         "pareto,pareto_technique";
  if (terms)
    for (const LightTerm term : kLightTerms)
      csv << ",rel_mse_" << termName(term) << ",share_" << termName(term) << ",brightness_"
          << termName(term);
  csv << "\n";
}

void csvRow(std::ostream& csv, const Job& job, const Measured& measured,
            const std::vector<Sweep>& sweeps, const std::vector<std::string>& stages, bool onFront,
            bool onTechniqueFront, bool terms) {
  csv << job.technique;
  for (const Sweep& s : sweeps) {
    csv << ",";
    for (const auto& [key, value] : job.values)
      if (key == s.key) csv << value;
  }
  const Result& result = measured.result;
  csv << "," << job.label() << "," << result.seconds;
  for (const std::string& s : stages) {
    csv << ",";
    const auto it = result.stages.find(s);
    if (it != result.stages.end()) csv << it->second;
  }
  const reference::ImageMetrics& m = measured.metrics;
  // What a unit of error costs in time: 1 / (seconds x MSE), as voxgi bench path reports it.
  const double efficiency = 1.0 / (result.seconds * m.rmse * m.rmse);
  csv << "," << metricCells(m) << ",";
  if (measured.directOnly)
    csv << errorCells(*measured.directOnly) << ",";
  else
    csv << ",,,,,";
  if (std::isfinite(efficiency)) csv << efficiency;
  csv << "," << (onFront ? 1 : 0) << "," << (onTechniqueFront ? 1 : 0);
  if (terms) {
    // A technique without terms leaves its cells empty.
    for (size_t t = 0; t < kLightTerms.size(); ++t) {
      if (measured.terms.empty()) {
        csv << ",,,";
        continue;
      }
      const reference::TermMetrics& tm = measured.terms[t];
      csv << "," << tm.own.relMse << "," << tm.share << ",";
      if (!std::isnan(tm.meanRatio)) csv << tm.meanRatio;
    }
  }
  csv << "\n";
}

// The trivial answers as rows of their own: no time, no front.
void csvBaselines(std::ostream& csv, const reference::Baselines& baselines, size_t sweeps,
                  size_t stages, bool terms) {
  for (const auto& [name, b] :
       {std::pair{"black", &baselines.black}, std::pair{"constant", &baselines.constant}}) {
    csv << "baseline_" << name << std::string(sweeps, ',') << "," << name << ",";
    for (size_t s = 0; s < stages; ++s) csv << ",";
    csv << "," << metricCells(*b) << ",,,,,,,0,0";
    if (terms) csv << std::string(3 * kLightTerms.size(), ',');
    csv << "\n";
  }
}

// The plot, with the reference's noise floor where its variance image gives one.
void plotStudy(const StudyOptions& o, const StudyReference& ref) {
  std::string noiseFloor;
  const std::optional<Image> variance = readVarianceImage(o.reference, ref.image);
  if (variance && (o.metric == "rmse" || o.metric == "rel_mse")) {
    const reference::ImageMetrics floor =
        reference::noiseFloor(ref.image, *variance, ref.mask, ref.scale);
    noiseFloor = std::to_string(o.metric == "rmse" ? floor.rmse : floor.relMse);
  }
  const std::string title = std::filesystem::path(o.scene).filename().string() + " against " +
                            std::filesystem::path(o.reference).filename().string();
  plot(o.csv, o.plot, o.metric, title, noiseFloor);
  std::cout << "wrote " << o.plot << "\n";
}

// A study's jobs and reference, checked before anything runs.
struct StudyPlan {
  std::vector<Sweep> sweeps;
  StudyReference ref;
  std::vector<Job> jobs;
};

StudyPlan planStudy(const StudyOptions& o) {
  StudyPlan plan;
  for (const std::string& s : o.sweeps) plan.sweeps.push_back(parseSweep(s));
  plan.ref = readStudyReference(o);
  plan.jobs = makeJobs(o, plan.sweeps);
  checkSameSize(plan.jobs.front().scene.camera.width, plan.jobs.front().scene.camera.height,
                o.scene + " camera.resolution (or --image)", plan.ref.image);
  return plan;
}

void checkOutputs(const StudyOptions& o) {
  checkOutputPath(o.csv);
  if (!o.plot.empty()) checkOutputPath(o.plot);
}

void printProgress(size_t k, size_t count, const Job& job, const Measured& measured) {
  const reference::ImageMetrics& m = measured.metrics;
  std::cout << "[" << k + 1 << "/" << count << "] " << job.technique << " " << job.label() << ": "
            << measured.result.seconds << " s, RMSE " << m.rmse << ", relMSE " << m.relMse
            << ", SSIM " << m.ssim << ", energy " << m.energy.r << " / " << m.energy.g << " / "
            << m.energy.b << std::endl;
}

// Metrics as a record holds them: voxgi compare's names, NaN as null, doubles exact.
nlohmann::json metricsRecord(const reference::ImageMetrics& m) {
  nlohmann::json j = metricsJson(m);
  j["pixels"] = m.pixels;
  return j;
}

double numberOf(const nlohmann::json& v) {
  return v.is_null() ? std::nan("") : v.get<double>();
}

reference::ImageMetrics metricsFrom(const nlohmann::json& j) {
  reference::ImageMetrics m;
  m.rmse = numberOf(j.at("rmse"));
  m.relMse = numberOf(j.at("rel_mse"));
  m.mare = numberOf(j.at("mare"));
  m.ssim = numberOf(j.at("ssim"));
  for (int c = 0; c < 3; ++c) m.energy[c] = numberOf(j.at("energy").at(size_t(c)));
  m.pixels = j.at("pixels").get<size_t>();
  return m;
}

// What the CSV needs of a job's run, as JSON (the image itself stays where it ran).
nlohmann::json record(size_t k, const Job& job, const Measured& m) {
  nlohmann::json terms = nlohmann::json::array();
  for (const reference::TermMetrics& t : m.terms)
    terms.push_back({{"own", metricsRecord(t.own)},
                     {"share", numberOrNull(t.share)},
                     {"brightness", numberOrNull(t.meanRatio)}});
  return {{"job", k},
          {"technique", job.technique},
          {"label", job.label()},
          {"seconds", m.result.seconds},
          {"stages", m.result.stages},
          {"metrics", metricsRecord(m.metrics)},
          {"direct_only", m.directOnly ? metricsRecord(*m.directOnly) : nlohmann::json()},
          {"terms", terms}};
}

Measured measuredFrom(const nlohmann::json& r) {
  try {
    Measured m;
    m.result.seconds = r.at("seconds").get<double>();
    m.result.stages = r.at("stages").get<std::map<std::string, double>>();
    m.metrics = metricsFrom(r.at("metrics"));
    if (!r.at("direct_only").is_null()) m.directOnly = metricsFrom(r.at("direct_only"));
    for (const nlohmann::json& t : r.at("terms"))
      m.terms.push_back(
          {metricsFrom(t.at("own")), numberOf(t.at("share")), numberOf(t.at("brightness"))});
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("study", "job record", std::string("malformed: ") + e.what());
  }
}

// The records of the study's jobs `jobs`, each run here.
std::vector<nlohmann::json> measureJobs(const StudyOptions& o, const StudyPlan& plan,
                                        const std::vector<size_t>& jobs) {
  std::unique_ptr<gpu::GlContext> context;
  std::vector<nlohmann::json> records;
  for (const size_t k : jobs) {
    if (k >= plan.jobs.size())
      throw InputError("study", "job",
                       "the study has " + std::to_string(plan.jobs.size()) + " jobs, no job " +
                           std::to_string(k));
    const Measured m = measure(plan.jobs[k], o, plan.ref, context);
    printProgress(k, plan.jobs.size(), plan.jobs[k], m);
    records.push_back(record(k, plan.jobs[k], m));
  }
  return records;
}

// The CSV (with the baselines and the Pareto fronts) and the plot of every job's measurements.
int writeResults(const StudyOptions& o, const StudyPlan& plan,
                 const std::vector<Measured>& measured) {
  const std::vector<Job>& jobs = plan.jobs;
  const StudyReference& ref = plan.ref;
  const reference::Baselines baselines =
      reference::trivialBaselines(ref.image, ref.mask, ref.scale);
  std::cout << "baselines: black relMSE " << baselines.black.relMse << ", SSIM "
            << baselines.black.ssim << "; constant relMSE " << baselines.constant.relMse
            << ", SSIM " << baselines.constant.ssim << std::endl;
  const Fronts fronts = paretoFronts(o, jobs, measured);
  const std::vector<std::string> stages = stageColumns(o);
  const bool terms = ref.terms.has_value();
  std::ostringstream csv;
  csvHeader(csv, plan.sweeps, stages, terms);
  csv.precision(6);
  for (size_t k = 0; k < jobs.size(); ++k)
    csvRow(csv, jobs[k], measured[k], plan.sweeps, stages, fronts.all[k], fronts.ownTechnique[k],
           terms);
  csvBaselines(csv, baselines, plan.sweeps.size(), stages.size(), terms);
  writeFileAtomically(o.csv, csv.str());
  std::cout << "wrote " << o.csv << " (" << jobs.size() << " rows)\n";
  if (!o.plot.empty()) plotStudy(o, ref);
  return kExitOk;
}

}  // namespace

Scene loadStudyScene(const StudyOptions& o) {
  Scene scene = loadScene(o.scene);
  if (o.image != 0) setImageWidth(scene, o.image, "--image");
  if (o.resolution != 0) {
    scene.grid.resolution = readResolution("--resolution", "", o.resolution);
    checkGrid(scene, "--resolution " + std::to_string(o.resolution));
  }
  return scene;
}

double metricError(const reference::ImageMetrics& m, const std::string& metric) {
  return metric == "rmse"      ? m.rmse
         : metric == "rel_mse" ? m.relMse
         : metric == "mare"    ? m.mare
                               : 1.0 - m.ssim;
}

std::string metricLabel(const std::string& metric) {
  return metric == "rmse"      ? "RMSE"
         : metric == "rel_mse" ? "relative MSE"
         : metric == "mare"    ? "mean absolute relative error"
                               : "1 - SSIM";
}

int runStudy(const StudyOptions& o) {
  if (!o.frames.empty()) {
    if (!o.shard.empty() || o.merge > 0)
      throw InputError(o.shard.empty() ? "--merge" : "--shard", "",
                       "a study in time (--frames) runs in one piece");
    return runStudyFrames(o);
  }
  if (!o.shard.empty()) return runStudyShard(o);
  if (o.merge > 0) return runStudyMerge(o);
  checkOutputs(o);
  const StudyPlan plan = planStudy(o);
  std::unique_ptr<gpu::GlContext> context;
  std::vector<Measured> measured;
  for (size_t k = 0; k < plan.jobs.size(); ++k) {
    measured.push_back(measure(plan.jobs[k], o, plan.ref, context));
    printProgress(k, plan.jobs.size(), plan.jobs[k], measured.back());
  }
  return writeResults(o, plan, measured);
}

size_t studyJobCount(const StudyOptions& o) {
  std::vector<Sweep> sweeps;
  for (const std::string& s : o.sweeps) sweeps.push_back(parseSweep(s));
  return makeJobs(o, sweeps).size();
}

std::vector<nlohmann::json> runStudyJobs(const StudyOptions& o, const std::vector<size_t>& jobs) {
  return measureJobs(o, planStudy(o), jobs);
}

std::vector<nlohmann::json> runStudyJobs(const StudyOptions& o, const Shard& shard) {
  const StudyPlan plan = planStudy(o);
  std::vector<size_t> mine;
  for (size_t k = 0; k < plan.jobs.size(); ++k)
    if (shard.owns(k)) mine.push_back(k);
  return measureJobs(o, plan, mine);
}

int writeStudy(const StudyOptions& o, const std::vector<nlohmann::json>& records) {
  checkOutputs(o);
  const StudyPlan plan = planStudy(o);
  std::vector<Measured> measured(plan.jobs.size());
  std::vector<bool> seen(plan.jobs.size(), false);
  for (const nlohmann::json& r : records) {
    const size_t k = r.at("job").get<size_t>();
    if (k >= plan.jobs.size() || seen[k] || r.at("technique") != plan.jobs[k].technique ||
        r.at("label") != plan.jobs[k].label())
      throw InputError("study", "job " + std::to_string(k),
                       seen.size() > k && seen[k]
                           ? "given twice"
                           : "is not this study's (another study's record, or other options)");
    seen[k] = true;
    measured[k] = measuredFrom(r);
  }
  for (size_t k = 0; k < seen.size(); ++k)
    if (!seen[k])
      throw InputError(
          "study", "job " + std::to_string(k),
          "missing: no record of it among the " + std::to_string(records.size()) + " given");
  return writeResults(o, plan, measured);
}

void addStudyCommand(CLI::App& app, Commands& commands) {
  auto o = std::make_shared<StudyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "study", "sweep parameters, time each combination and plot its error against a reference");
  addStudyOptions(*cmd, *o);
  commands.push_back({cmd, [o] { return runStudy(*o); }});
}

}  // namespace voxgi::tools
