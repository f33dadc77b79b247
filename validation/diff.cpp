#include "validation/diff.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "common/buffer_io.h"
#include "validation/comparisons.h"
#include "validation/stage_functions.h"

namespace voxgi::validation {
namespace {

// Distance in units in the last place between two floats (same sign ordering, NaN = infinite).
double ulpDistance(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<double>::infinity();
  auto ordered = [](float f) {
    int32_t i;
    std::memcpy(&i, &f, sizeof i);
    return i < 0 ? int64_t(std::numeric_limits<int32_t>::min()) - i : int64_t(i);
  };
  return std::abs(static_cast<double>(ordered(a) - ordered(b)));
}

TieClassifier classifierFor(std::string_view stage, const StageContext& ctx, const BufferSet& cpu,
                            const BufferSet& gpu) {
  if (stage == "voxelize") return voxelizeTies(ctx);
  if (stage == "gbuffer") return gbufferTies(cpu, gpu);
  return {};
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void dump(const std::string& dir, const StageReport& report, const BufferSet& cpu,
          const BufferSet& gpu, const GridSpec& grid) {
  std::filesystem::create_directories(dir);
  const std::string prefix = dir + "/" + report.stage;
  std::vector<const Buffer*> cpuList, gpuList, diffList;
  // The difference grids reuse the buffer names but hold gpu - cpu as f32.
  std::vector<BufferSpec> diffSpecs;
  for (const BufferSpec* spec : stageBuffers(report.stage))
    diffSpecs.push_back({spec->stage, spec->name, ScalarType::f32, spec->components, spec->shape,
                         spec->need, spec->meaning});
  std::vector<Buffer> diffs;
  diffs.reserve(diffSpecs.size());
  for (const BufferSpec& spec : diffSpecs) {
    const auto c = cpu.find(spec.name), g = gpu.find(spec.name);
    if (c == cpu.end() || g == gpu.end() || c->second.extent != g->second.extent) continue;
    cpuList.push_back(&c->second);
    gpuList.push_back(&g->second);
    Buffer d(spec, c->second.extent);
    for (size_t e = 0; e < d.elementCount(); ++e)
      for (int k = 0; k < spec.components; ++k)
        d.set(e, k, static_cast<float>(g->second.value(e, k) - c->second.value(e, k)));
    diffs.push_back(std::move(d));
  }
  for (const Buffer& d : diffs) diffList.push_back(&d);
  // Per element of the stage (all its buffers share one shape and extent).
  BufferSpec classSpec{"",
                       "classification",
                       ScalarType::i32,
                       1,
                       BufferShape::volume,
                       BufferNeed::always,
                       "0 agree, 1 tie, 2 not a tie"};
  Buffer classes;
  if (!cpuList.empty()) {
    classSpec.shape = cpuList[0]->spec->shape;
    classes = Buffer(classSpec, cpuList[0]->extent);
    for (const auto& [element, kind] : report.outside)
      if (element < classes.elementCount()) classes.set<int32_t>(element, 0, int32_t(kind));
    diffList.push_back(&classes);
  }
  writeBuffers(prefix + "_cpu", cpuList, grid, {{"voxgi_backend", "cpu"}});
  writeBuffers(prefix + "_gpu", gpuList, grid, {{"voxgi_backend", "gpu"}});
  writeBuffers(prefix + "_diff", diffList, grid, {{"voxgi_backend", "gpu minus cpu"}});
}

}  // namespace

StageReport compareStage(std::string_view stage, const BufferSet& cpu, const BufferSet& gpu,
                         const TieClassifier& classify) {
  StageReport report;
  report.stage = std::string(stage);
  // Classifying is costly (it revisits nearby geometry): each element is classified once, for
  // all buffers, and at most kMaxClassified elements per stage.
  constexpr size_t kMaxClassified = 20000;
  size_t classified = 0;
  std::map<size_t, bool> decided;  // element -> tie (false also for unclassified)
  for (const BufferSpec* spec : stageBuffers(stage)) {
    const Comparison& cmp = comparisonFor(stage, spec->name);
    BufferReport r;
    r.buffer = std::string(spec->name);
    r.metric = cmp.describe();
    r.tolerance = cmp.tolerance;
    r.reason = std::string(cmp.reason);
    const auto c = cpu.find(spec->name), g = gpu.find(spec->name);
    if (c == cpu.end() && g == gpu.end()) {
      r.status = "not produced by either backend (the scene does not need it)";
      report.buffers.push_back(r);
      continue;
    }
    if (c == cpu.end() || g == gpu.end() || c->second.extent != g->second.extent) {
      r.status = c == cpu.end()   ? "missing on cpu"
                 : g == gpu.end() ? "missing on gpu"
                                  : "extents differ";
      r.pass = false;
      report.pass = false;
      report.buffers.push_back(r);
      continue;
    }
    r.status = "compared";
    const Buffer& a = c->second;
    const Buffer& b = g->second;
    r.elements = a.elementCount();
    double worst = -1.0;
    for (size_t e = 0; e < r.elements; ++e) {
      bool outside = false;
      double elementWorst = 0.0;
      double magnitude = 0.0;  // for max_rel
      if (cmp.metric == Metric::max_rel)
        for (int k = 0; k < spec->components; ++k)
          magnitude = std::max({magnitude, std::abs(a.value(e, k)), std::abs(b.value(e, k))});
      for (int k = 0; k < spec->components; ++k) {
        const size_t w = e * size_t(spec->components) + size_t(k);
        if (a.words[w] == b.words[w]) continue;
        const double abs = std::abs(b.value(e, k) - a.value(e, k));
        r.maxAbsDiff = std::max(r.maxAbsDiff, abs);
        elementWorst = std::max(elementWorst, abs);
        if (spec->type == ScalarType::f32) {
          const double ulp = ulpDistance(a.get<float>(e, k), b.get<float>(e, k));
          r.maxUlp = std::max(r.maxUlp, ulp);
          if (cmp.metric == Metric::max_ulp) outside |= ulp > cmp.tolerance;
        }
        if (cmp.metric == Metric::exact) outside = true;
        if (cmp.metric == Metric::max_abs) outside |= !(abs <= cmp.tolerance);
        if (cmp.metric == Metric::max_rel) outside |= !(abs <= cmp.tolerance * magnitude);
      }
      if (elementWorst > worst && elementWorst > 0.0) {
        worst = elementWorst;
        r.worstElement = static_cast<long long>(e);
      }
      if (!outside) continue;
      ++r.differing;
      auto known = decided.find(e);
      if (known == decided.end()) {
        const bool canClassify = classify && classified < kMaxClassified;
        classified += canClassify;
        known = decided.emplace(e, canClassify && classify(e)).first;
        if (!canClassify)
          ++r.unclassified;
        else
          known->second ? ++r.ties : ++r.nonTies;
      } else {
        known->second ? ++r.ties : ++r.nonTies;
      }
      report.outside[e] = known->second ? ElementClass::tie : ElementClass::not_a_tie;
    }
    r.fraction = r.elements ? double(r.differing) / double(r.elements) : 0.0;
    r.pass = r.nonTies == 0 && r.unclassified == 0;
    report.pass &= r.pass;
    report.buffers.push_back(r);
  }
  return report;
}

std::vector<StageReport> diffStages(const Scene& scene, const Settings& settings,
                                    gpu::GlContext& context, const std::vector<std::string>& stages,
                                    const std::string& dumpDir) {
  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{scene, settings, triangles};
  std::vector<StageReport> reports;
  BufferSet inputs;  // the CPU's outputs of the stages run so far
  for (const StageFunctions& stage : stageFunctions()) {
    BufferSet cpuOut = inputs, gpuOut = inputs;
    auto start = std::chrono::steady_clock::now();
    stage.cpu(ctx, cpuOut);
    const double cpuSeconds = seconds(start);
    const bool wanted = std::find(stages.begin(), stages.end(), stage.name) != stages.end();
    if (wanted) {
      start = std::chrono::steady_clock::now();
      stage.gpu(context, ctx, gpuOut);
      const double gpuSeconds = seconds(start);
      const TieClassifier classify = classifierFor(stage.name, ctx, cpuOut, gpuOut);
      StageReport report = compareStage(stage.name, cpuOut, gpuOut, classify);
      report.cpuSeconds = cpuSeconds;
      report.gpuSeconds = gpuSeconds;
      if (!dumpDir.empty()) dump(dumpDir, report, cpuOut, gpuOut, scene.grid);
      reports.push_back(std::move(report));
    }
    inputs = std::move(cpuOut);
  }
  return reports;
}

}  // namespace voxgi::validation
