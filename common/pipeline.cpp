#include "common/pipeline.h"

#include <chrono>
#include <map>
#include <stdexcept>

#include "common/error.h"

namespace voxgi {
namespace {

std::string names(const std::vector<const BufferSpec*>& specs) {
  std::string out;
  for (const BufferSpec* b : specs) out.append(out.empty() ? "" : ", ").append(b->qualifiedName());
  return out;
}

}  // namespace

std::string StageOutputs::describe(const StageSpec& stage, const std::string& backend) const {
  std::string out = stage.qualifiedName() + " on " + backend + ":";
  if (!missing.empty()) out += " did not write planned " + names(missing) + ";";
  if (!unplanned.empty()) out += " wrote unplanned " + names(unplanned) + ";";
  return out;
}

std::vector<const StageSpec*> plannedStages(const StageContext& ctx, const StageSpec* last) {
  std::vector<const StageSpec*> out;
  for (const StageSpec* s : ctx.technique.steps()) {
    if (!ctx.plan.decides(s->id))
      throw std::logic_error(std::string(ctx.technique.name) + "'s planner (common/" +
                             std::string(ctx.technique.stages) + "/plan.cpp) does not decide " +
                             s->qualifiedName());
    if (ctx.plan.runs(s->id)) out.push_back(s);
    if (s == last) break;
  }
  return out;
}

StageOutputs runStage(StageBackend& backend, const StageSpec& stage, const StageContext& ctx,
                      BufferSet& buffers) {
  const std::vector<const BufferSpec*> own = stageBuffers(stage);
  // A rerun starts from its inputs alone; the frame before's buffers go to a stage that updates
  // them in part.
  if (ctx.previous) ctx.previous->stash = BufferSet{};
  for (const BufferSpec* b : own) {
    Buffer old = buffers.take(b->id);
    if (ctx.previous && old.spec != nullptr) ctx.previous->stash.put(std::move(old));
  }
  // Other stages' buffers by where their words live: a stage that replaced one moved them.
  std::map<BufferId, const uint32_t*> before;
  for (const auto& [id, b] : buffers) before[id] = b.words.data();
  if (ctx.plan.dark)
    putDarkOutputs(ctx, stage.id, buffers);
  else
    backend.run(stage.id, ctx, buffers);
  if (ctx.previous) ctx.previous->stash = BufferSet{};
  StageOutputs r;
  for (const BufferSpec* b : own) {
    const bool written = buffers.contains(b->id), planned = bufferNeeded(*b, ctx.plan);
    if (planned && !written) r.missing.push_back(b);
    if (written && !planned) r.unplanned.push_back(b);
  }
  for (const auto& [id, b] : buffers) {
    if (bufferSpec(id).stage == stage.id) continue;
    const auto it = before.find(id);
    if (it == before.end() || it->second != b.words.data()) r.unplanned.push_back(&bufferSpec(id));
  }
  return r;
}

void runPipeline(StageBackend& backend, const StageContext& ctx, BufferSet& buffers,
                 const StageSpec* last, const StageObserver& observe) {
  for (const StageSpec* stage : plannedStages(ctx, last)) {
    const auto start = std::chrono::steady_clock::now();
    const StageOutputs outputs = runStage(backend, *stage, ctx, buffers);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!outputs.ok()) throw std::logic_error(outputs.describe(*stage, backend.name()));
    if (observe) observe(*stage, seconds);
  }
}

const StageSpec& resolveStage(const Technique& technique, const std::string& text,
                              const std::string& source) {
  const size_t slash = text.find('/');
  const std::string owner = slash == std::string::npos ? "" : text.substr(0, slash);
  const std::string name = slash == std::string::npos ? text : text.substr(slash + 1);
  std::string known;
  for (const StageSpec* s : technique.steps()) {
    known.append(known.empty() ? "" : ", ").append(s->qualifiedName());
    if (s->name != name) continue;
    if (owner.empty() || owner == s->owner ||
        (owner == technique.name && (s->shared() || s->owner == technique.stages)))
      return *s;
  }
  throw InputError(
      source, "", "no stage '" + text + "' in " + std::string(technique.name) + " (" + known + ")");
}

}  // namespace voxgi
