#include "validation/check.h"

#include <algorithm>

#include "common/error.h"
#include "validation/comparisons.h"

namespace voxgi::validation {
namespace {

std::string extentText(glm::ivec3 e) {
  return std::to_string(e.x) + " x " + std::to_string(e.y) + " x " + std::to_string(e.z);
}

}  // namespace

const StageSpec& candidateStage(const BufferSet& candidate, const std::string& source) {
  if (candidate.size() == 0) throw InputError(source, "", "no buffers to check");
  const StageSpec& stage = candidate.begin()->second.spec->stageSpec();
  for (const auto& [id, b] : candidate)
    if (b.spec->stage != stage.id)
      throw InputError(source, std::string(b.spec->qualifiedName()),
                       "buffers of one stage at a time: this one is " +
                           b.spec->stageSpec().qualifiedName() + "'s, the first " +
                           stage.qualifiedName() + "'s");
  return stage;
}

void requireOracle(const StageContext& ctx, const StageSpec& stage) {
  if (!ctx.plan.runs(stage.id))
    throw InputError("check", stage.qualifiedName(),
                     "the plan skips this stage for this scene (" + ctx.plan.whySkipped(stage.id) +
                         "), so there is no oracle to check against (voxgi plan says why)");
}

StageReport checkStage(const StageContext& ctx, const BufferSet& oracle,
                       const BufferSet& candidate) {
  const StageSpec& stage = candidateStage(candidate, "check");
  requireOracle(ctx, stage);
  // The oracle's set with the candidate's buffers in place of its own: the comparison then sees
  // exactly one difference per candidate buffer, and the tie classifiers (which look at both
  // sides' geometry buffers, e.g. the gbuffer's triangle ids) see the candidate's where it gave
  // them.
  BufferSet test = oracle;
  std::vector<BufferReport> mismatched;
  for (const auto& [id, b] : candidate) {
    const Buffer* own = oracle.find(id);
    if (own != nullptr && own->extent != b.extent) {
      const Comparison& cmp = comparisonFor(id);
      BufferReport r;
      r.buffer = std::string(b.spec->name);
      r.metric = cmp.describe();
      r.tolerance = cmp.tolerance;
      r.reason = std::string(cmp.reason);
      r.status = "extent " + extentText(b.extent) + ", the oracle's " + extentText(own->extent);
      r.pass = false;
      mismatched.push_back(r);
      continue;
    }
    test.put(b);
  }
  const TieClassifier classify = stageTies(stage, ctx, oracle, test);
  StageReport report = compareStage(stage, ctx.plan, oracle, test, classify);
  // Only the candidate's buffers: the others are the oracle's on both sides.
  std::erase_if(report.buffers, [&](const BufferReport& r) {
    return std::none_of(candidate.begin(), candidate.end(),
                        [&](const auto& entry) { return entry.second.spec->name == r.buffer; });
  });
  report.buffers.insert(report.buffers.end(), mismatched.begin(), mismatched.end());
  report.pass = std::all_of(report.buffers.begin(), report.buffers.end(),
                            [](const BufferReport& r) { return r.pass; });
  return report;
}

}  // namespace voxgi::validation
