#include "validation/diff.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "common/io/buffer_io.h"
#include "common/io/output_file.h"
#include "common/technique.h"
#include "validation/comparisons.h"

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

// The same for two halves' bits (an f16 buffer's components; NaN = infinite), in ULPs of a half.
double halfUlpDistance(uint32_t a, uint32_t b) {
  const auto nan = [](uint32_t h) { return (h & 0x7c00u) == 0x7c00u && (h & 0x3ffu) != 0; };
  if (nan(a) || nan(b)) return std::numeric_limits<double>::infinity();
  const auto ordered = [](uint32_t h) {
    const int32_t magnitude = int32_t(h & 0x7fffu);
    return (h & 0x8000u) != 0 ? -magnitude : magnitude;
  };
  return std::abs(static_cast<double>(ordered(a) - ordered(b)));
}

}  // namespace

TieClassifier stageTies(const StageSpec& stage, const StageContext& ctx, const BufferSet& cpu,
                        const BufferSet& gpu) {
  switch (comparisonFor(stageBuffers(stage).front()->id).ties) {
    case Ties::none:
      return {};
    case Ties::voxel_boundaries:
      return voxelizeTies(ctx);
    case Ties::pixel_edges:
      return gbufferTies(ctx, cpu, gpu);
    case Ties::texel_edges:
      return mapTies(stage, cpu, gpu);
  }
  return {};
}

namespace {

// The relative tolerance of element e of a buffer whose comparison widens with f16 steps, under a
// plan that stores half floats: a rounding that falls the other way on the two backends moves a
// value by one half ULP (2^-11), and each step can carry that on, so the buffer allows 2^-10 per
// step up to the element's (a series buffer's volume k: k + 1 steps; any other: every step). A
// buffer stored as halves (half_rounding) allows one ULP of a half more: 2^-10 of the element.
double widenedTolerance(const Comparison& cmp, const BufferSpec& spec, const EffectPlan& plan,
                        const Buffer& b, size_t e) {
  const double tolerance = cmp.tolerance;
  if (cmp.widening == Widening::half_rounding) return tolerance + std::ldexp(1.0, -10);
  if (cmp.widening != Widening::f16_steps || !plan.on(Effect::f16) || spec.type != ScalarType::f32)
    return tolerance;
  const size_t volume = size_t(b.extent.x) * size_t(b.extent.x) * size_t(b.extent.x);
  const double steps =
      spec.shape == BufferShape::series ? double(e / volume + 1) : double(plan.seriesLength);
  return std::max(tolerance, std::ldexp(steps, -10));
}

// What a max_rel comparison allows on top of its relative tolerance: one subnormal half's spacing
// (2^-24) for a buffer stored as halves, where a ULP is no longer relative to the value.
double absoluteSlack(const Comparison& cmp) {
  return cmp.widening == Widening::half_rounding ? std::ldexp(1.0, -24) : 0.0;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void dump(const std::string& dir, const StageSpec& stage, const StageReport& report,
          const BufferSet& cpu, const BufferSet& gpu, const StageContext& ctx) {
  const GridSpec& grid = ctx.scene.grid;
  prepareOutputFolder(dir);
  const std::string prefix = dir + "/" + std::string(stage.name);
  std::vector<const Buffer*> cpuList, gpuList, diffList;
  // The difference grids reuse the buffer names but hold gpu - cpu as f32.
  std::vector<BufferSpec> diffSpecs;
  for (const BufferSpec* spec : stageBuffers(stage)) {
    diffSpecs.push_back(*spec);
    diffSpecs.back().type = ScalarType::f32;
  }
  std::vector<Buffer> diffs;
  diffs.reserve(diffSpecs.size());
  for (const BufferSpec& spec : diffSpecs) {
    const Buffer *c = cpu.find(spec.id), *g = gpu.find(spec.id);
    if (c == nullptr || g == nullptr || c->extent != g->extent) continue;
    cpuList.push_back(c);
    gpuList.push_back(g);
    Buffer d(spec, c->extent);
    for (size_t e = 0; e < d.elementCount(); ++e)
      for (int k = 0; k < spec.components; ++k)
        d.set(e, k, static_cast<float>(g->value(e, k) - c->value(e, k)));
    diffs.push_back(std::move(d));
  }
  for (const Buffer& d : diffs) diffList.push_back(&d);
  // Per element of the stage (all its buffers share one shape and extent).
  BufferSpec classSpec = *stageBuffers(stage).front();
  classSpec.name = "classification";
  classSpec.type = ScalarType::i32;
  classSpec.components = 1;
  classSpec.meaning = "0 agree, 1 tie, 2 not a tie";
  Buffer classes;
  if (!cpuList.empty()) {
    classSpec.shape = cpuList[0]->spec->shape;
    classes = Buffer(classSpec, cpuList[0]->extent);
    for (const auto& [element, kind] : report.outside)
      if (element < classes.elementCount()) classes.set<int32_t>(element, 0, int32_t(kind));
    diffList.push_back(&classes);
  }
  // Sparse buffers are placed by the CPU's run: the GPU's is in the same canonical order.
  const SparseLayouts layouts = ctx.technique.sparseLayouts(cpu, grid);
  writeBuffers(prefix + "_cpu", cpuList, grid, {{"voxgi_backend", "cpu"}}, layouts);
  writeBuffers(prefix + "_gpu", gpuList, grid, {{"voxgi_backend", "gpu"}}, layouts);
  writeBuffers(prefix + "_diff", diffList, grid, {{"voxgi_backend", "gpu minus cpu"}}, layouts);
}

}  // namespace

// The report of a buffer that is not compared: `why`, failing unless `pass`.
BufferReport uncompared(const BufferSpec& spec, std::string why, bool pass) {
  const Comparison& cmp = comparisonFor(spec.id);
  BufferReport r;
  r.buffer = std::string(spec.name);
  r.metric = cmp.describe();
  r.tolerance = cmp.tolerance;
  r.reason = std::string(cmp.reason);
  r.status = std::move(why);
  r.pass = pass;
  return r;
}

// Failures of a stage that wrote another stage's buffers (runStage's unplanned list).
void reportForeignWrites(StageReport& report, const StageSpec& stage, const StageOutputs& outputs,
                         const std::string& backend) {
  for (const BufferSpec* b : outputs.unplanned) {
    if (b->stage == stage.id) continue;  // its own: compareStage reports those
    report.buffers.push_back(uncompared(*b,
                                        "written by " + stage.qualifiedName() + " on " + backend +
                                            ", but " + b->qualifiedName() +
                                            " belongs to another stage",
                                        false));
    report.pass = false;
  }
}

StageReport compareStage(const StageSpec& stage, const EffectPlan& plan, const BufferSet& cpu,
                         const BufferSet& gpu, const TieClassifier& classify) {
  StageReport report;
  report.stage = stage.qualifiedName();
  // Classifying is costly (it revisits nearby geometry): each element is classified once, for
  // all buffers, and at most kMaxClassified elements per stage.
  constexpr size_t kMaxClassified = 20000;
  size_t classified = 0;
  std::map<size_t, bool> decided;  // element -> tie (false also for unclassified)
  for (const BufferSpec* spec : stageBuffers(stage)) {
    const Comparison& cmp = comparisonFor(spec->id);
    const Buffer *c = cpu.find(spec->id), *g = gpu.find(spec->id);
    const bool planned = bufferNeeded(*spec, plan);
    std::string problem;  // why the buffer fails without being compared
    if (!planned && c == nullptr && g == nullptr) {
      report.buffers.push_back(uncompared(
          *spec,
          "not planned: needs " + std::string(effectSpec(spec->need).name) + ", which is off",
          true));
      continue;
    }
    if (!planned)
      problem = std::string("not planned, but produced on ") + (c != nullptr && g != nullptr
                                                                    ? "both backends"
                                                                : c != nullptr ? "cpu"
                                                                               : "gpu");
    else if (c == nullptr || g == nullptr)
      problem =
          std::string("planned, but missing on ") + (c == nullptr && g == nullptr ? "both backends"
                                                     : c == nullptr               ? "cpu"
                                                                                  : "gpu");
    else if (c->extent != g->extent)
      problem = "extents differ";
    if (!problem.empty()) {
      report.buffers.push_back(uncompared(*spec, problem, false));
      report.pass = false;
      continue;
    }
    BufferReport r = uncompared(*spec, "compared", true);
    const Buffer& a = *c;
    const Buffer& b = *g;
    r.elements = a.elementCount();
    double worst = -1.0;
    for (size_t e = 0; e < r.elements; ++e) {
      bool outside = false;
      double elementWorst = 0.0;
      double magnitude = 0.0;  // for max_rel
      double relative = cmp.tolerance;
      if (cmp.metric == Metric::max_rel) {
        for (int k = 0; k < spec->components; ++k)
          magnitude = std::max({magnitude, std::abs(a.value(e, k)), std::abs(b.value(e, k))});
        relative = widenedTolerance(cmp, *spec, plan, a, e);
      }
      for (int k = 0; k < spec->components; ++k) {
        if (a.bitsAt(e, k) == b.bitsAt(e, k)) continue;
        const double abs = std::abs(b.value(e, k) - a.value(e, k));
        r.maxAbsDiff = std::max(r.maxAbsDiff, abs);
        elementWorst = std::max(elementWorst, abs);
        if (spec->type == ScalarType::f32 || spec->type == ScalarType::f16) {
          const double ulp = spec->type == ScalarType::f32
                                 ? ulpDistance(a.get<float>(e, k), b.get<float>(e, k))
                                 : halfUlpDistance(a.bitsAt(e, k), b.bitsAt(e, k));
          r.maxUlp = std::max(r.maxUlp, ulp);
          if (cmp.metric == Metric::max_ulp) outside |= ulp > cmp.tolerance;
        }
        if (cmp.metric == Metric::exact) outside = true;
        if (cmp.metric == Metric::max_abs) outside |= !(abs <= cmp.tolerance);
        if (cmp.metric == Metric::max_rel)
          outside |= !(abs <= relative * magnitude + absoluteSlack(cmp));
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

std::vector<StageReport> diffStages(const StageContext& ctx, StageBackend& cpu, StageBackend& gpu,
                                    const std::vector<const StageSpec*>& stages,
                                    const std::string& dumpDir) {
  std::vector<StageReport> reports;
  const auto wanted = [&](const StageSpec* s) {
    return std::find(stages.begin(), stages.end(), s) != stages.end();
  };
  // Requested stages the plan skips pass with the plan's reason (they produce nothing).
  for (const StageSpec* s : stages)
    if (!ctx.plan.runs(s->id)) {
      StageReport skipped;
      skipped.stage = s->qualifiedName();
      skipped.skipped = "skipped by the plan: " + ctx.plan.whySkipped(s->id);
      reports.push_back(std::move(skipped));
    }
  const StageSpec* last = nullptr;
  for (const StageSpec* s : ctx.technique.steps())
    if (wanted(s)) last = s;
  BufferSet inputs;  // the CPU's outputs of the stages run so far
  for (const StageSpec* stage : plannedStages(ctx, last)) {
    // In a sequence, the GPU gets the state stages carry as the CPU found it (ctx.history goes on
    // with the CPU's), as it gets the CPU's buffers.
    std::optional<FrameHistory> carried;
    if (ctx.history != nullptr && wanted(stage)) carried = *ctx.history;
    BufferSet cpuOut = inputs;
    auto start = std::chrono::steady_clock::now();
    const StageOutputs cpuOutputs = runStage(cpu, *stage, ctx, cpuOut);
    const double cpuSeconds = seconds(start);
    if (wanted(stage)) {
      BufferSet gpuOut = inputs;
      StageContext gpuCtx = ctx;
      gpuCtx.history = carried ? &*carried : nullptr;
      start = std::chrono::steady_clock::now();
      const StageOutputs gpuOutputs = runStage(gpu, *stage, gpuCtx, gpuOut);
      const double gpuSeconds = seconds(start);
      const TieClassifier classify = stageTies(*stage, ctx, cpuOut, gpuOut);
      StageReport report = compareStage(*stage, ctx.plan, cpuOut, gpuOut, classify);
      reportForeignWrites(report, *stage, cpuOutputs, cpu.name());
      reportForeignWrites(report, *stage, gpuOutputs, gpu.name());
      report.cpuSeconds = cpuSeconds;
      report.gpuSeconds = gpuSeconds;
      if (!dumpDir.empty()) dump(dumpDir, *stage, report, cpuOut, gpuOut, ctx);
      reports.push_back(std::move(report));
    } else if (!cpuOutputs.ok()) {
      // A later stage's inputs would be wrong: the CPU reference itself broke the plan.
      throw std::logic_error(cpuOutputs.describe(*stage, cpu.name()));
    }
    inputs = std::move(cpuOut);
  }
  return reports;
}

}  // namespace voxgi::validation
