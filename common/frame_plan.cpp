#include "common/frame_plan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/voxel_triangles.h"

namespace voxgi {

unsigned stageSceneInputs(StageId stage) {
  return stageSpec(stage).reads & stage_reads::kScene;
}

bool stageReadsBuffers(StageId stage) {
  return (stageSpec(stage).reads & stage_reads::buffers) != 0;
}

bool stageCarries(const StageContext& ctx, StageId stage) {
  return ctx.history != nullptr && (stageSpec(stage).reads & stage_reads::history) != 0 &&
         ctx.plan.carries(stage);
}

namespace {

std::string percent(size_t part, size_t whole) {
  const double p = whole == 0 ? 0.0 : 100.0 * double(part) / double(whole);
  char text[32];
  std::snprintf(text, sizeof text, p < 1.0 && part > 0 ? "%.2f %%" : "%.0f %%", p);
  return text;
}

std::string count(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string SceneChange::describe() const {
  if (what.empty()) return "nothing moved";
  std::string out;
  for (const std::string& w : what) out += (out.empty() ? "" : "; ") + w;
  return out;
}

SceneChange sceneChange(const Scene& before, const Scene& after) {
  SceneChange c;
  size_t movedMeshes = 0, movedTriangles = 0, triangles = 0;
  for (size_t i = 0; i < after.meshes.size(); ++i) {
    triangles += after.meshes[i].triangles.size();
    if (i >= before.meshes.size() || before.meshes[i].positions != after.meshes[i].positions) {
      ++movedMeshes;
      movedTriangles += after.meshes[i].triangles.size();
    }
  }
  if (movedMeshes > 0 || before.meshes.size() != after.meshes.size()) {
    c.parts |= stage_reads::geometry;
    c.what.push_back(count(movedMeshes, "mesh", "meshes") + " moved: " +
                     std::to_string(movedTriangles) + " of " + std::to_string(triangles) +
                     " triangles (" + percent(movedTriangles, triangles) + ")");
  }
  bool clouds = before.pointClouds.size() != after.pointClouds.size();
  for (size_t i = 0; !clouds && i < after.pointClouds.size(); ++i)
    clouds = before.pointClouds[i].positions != after.pointClouds[i].positions ||
             before.pointClouds[i].normals != after.pointClouds[i].normals ||
             before.pointClouds[i].radii != after.pointClouds[i].radii;
  if (clouds) {
    c.parts |= stage_reads::geometry;
    c.what.push_back("a point cloud moved");
  }
  if (before.lights != after.lights) {
    c.parts |= stage_reads::lights;
    size_t changed = 0;
    for (size_t i = 0; i < std::min(before.lights.size(), after.lights.size()); ++i)
      changed += before.lights[i] == after.lights[i] ? 0 : 1;
    c.what.push_back(before.lights.size() == after.lights.size()
                         ? count(changed, "light", "lights") + " changed"
                         : "the lights changed");
  }
  if (!(before.camera == after.camera)) {
    c.parts |= stage_reads::camera;
    c.what.push_back("the camera moved");
  }
  return c;
}

std::vector<FrameStep> frameSteps(const StageContext& ctx, const EffectPlan* previous,
                                  const SceneChange& change, const VolumeUpdate* volumes) {
  const std::vector<const StageSpec*> planned = plannedStages(ctx);
  std::vector<FrameStep> steps;
  if (previous == nullptr || !previous->sameDecisions(ctx.plan)) {
    for (const StageSpec* s : planned)
      steps.push_back({s, true, previous == nullptr ? "the first frame" : "the plan changed"});
    return steps;
  }
  const StageSpec* ran = nullptr;    // the first stage of the frame that runs
  bool volume = volumes != nullptr;  // before the first stage that reads the camera
  for (const StageSpec* s : planned) {
    volume = volume && (stageSceneInputs(s->id) & stage_reads::camera) == 0;
    if (volume && !volumes->due) {
      steps.push_back({s, false,
                       "update.interval: the volumes update in " +
                           count(size_t(volumes->framesLeft), "frame", "frames")});
      continue;
    }
    const SceneChange& since = volume ? volumes->change : change;
    const unsigned reads = stageSceneInputs(s->id) & since.parts;
    if (reads != 0) {
      std::vector<const char*> parts;
      if (reads & stage_reads::geometry) parts.push_back("geometry");
      if (reads & stage_reads::lights) parts.push_back("lights");
      if (reads & stage_reads::camera) parts.push_back("camera");
      std::string why = "it reads the changed ";
      for (size_t i = 0; i < parts.size(); ++i)
        why += std::string(i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
      steps.push_back({s, true, why});
      if (ran == nullptr) ran = s;
    } else if (ran != nullptr && stageReadsBuffers(s->id)) {
      steps.push_back({s, true, "after " + ran->qualifiedName() + ", which runs"});
    } else if (stageCarries(ctx, s->id) && ctx.history->settled.count(s->id) == 0) {
      steps.push_back({s, true, "it carries light from the frame before: one more bounce"});
      ran = s;
    } else {
      steps.push_back({s, false,
                       stageCarries(ctx, s->id) ? "the light it carries settled: reuse"
                       : since.parts == 0       ? "nothing moved: reuse"
                                                : "nothing it reads changed: reuse"});
    }
  }
  return steps;
}

void runFrame(StageBackend& backend, const StageContext& ctx, BufferSet& buffers,
              const std::vector<FrameStep>& steps, const StageObserver& observe) {
  for (const FrameStep& step : steps) {
    if (!step.runs) {
      for (const BufferSpec* spec : stageBuffers(*step.stage))
        if (bufferNeeded(*spec, ctx.plan) && !buffers.contains(spec->id))
          throw std::logic_error(step.stage->qualifiedName() + " is reused but its buffer " +
                                 std::string(spec->name) + " is not there");
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    const StageOutputs outputs = runStage(backend, *step.stage, ctx, buffers);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!outputs.ok()) throw std::logic_error(outputs.describe(*step.stage, backend.name()));
    if (observe) observe(*step.stage, seconds);
  }
}

FrameRunner::FrameRunner(const Technique& technique, StageBackend& backend, bool scratch)
    : technique_(technique), backend_(backend), scratch_(scratch) {}

const std::vector<FrameStep>& FrameRunner::run(Scene scene, const Settings& settings,
                                               const StageObserver& observe) {
  first_ = !plan_;
  change_ = first_ ? SceneChange{} : sceneChange(scene_, scene);
  previousScene_ = std::move(scene_);
  scene_ = std::move(scene);
  settings_ = settings;
  settings_.sequence = !scratch_;
  // Unmoved geometry keeps its prepared triangles.
  const bool prepare = first_ || scratch_ || (change_.parts & stage_reads::geometry) != 0;
  if (prepare) {
    previousTriangles_ = std::move(triangles_);
    // The meshes that did not move keep their triangles (same positions, same grid).
    std::vector<bool> unchanged;
    if (!first_ && !scratch_ && previousScene_.grid.min == scene_.grid.min &&
        previousScene_.grid.size == scene_.grid.size &&
        previousScene_.grid.resolution == scene_.grid.resolution &&
        previousScene_.meshes.size() == scene_.meshes.size())
      for (size_t m = 0; m < scene_.meshes.size(); ++m)
        unchanged.push_back(previousScene_.meshes[m].positions == scene_.meshes[m].positions);
    triangles_ = prepareVoxelTriangles(scene_, scene_.grid, previousTriangles_, unchanged);
  }
  StageContext ctx{technique_, scene_, settings_, triangles_};
  if (scratch_) buffers_ = BufferSet{};
  const bool same = !first_ && !scratch_ && plan_->sameDecisions(ctx.plan);
  PreviousFrame previous{&previousScene_, prepare ? &previousTriangles_ : &triangles_, {}};
  // update.interval > 1: the volumes come up to date on every N-th frame since they last did, and
  // what they update from is the scene they last ran on.
  const int interval = scratch_ ? 1 : settings_.updateInterval;
  std::optional<VolumeUpdate> volumes;
  if (interval > 1 && same) {
    volumes = VolumeUpdate{framesSinceUpdate_ + 1 >= interval, sceneChange(*volumeScene_, scene_),
                           interval - 1 - framesSinceUpdate_};  // frames until the next update
    previous = PreviousFrame{&*volumeScene_, &volumeTriangles_, {}};
  }
  if (same) ctx.previous = &previous;
  ctx.history = &history_;
  steps_ = frameSteps(ctx, scratch_ || first_ ? nullptr : &*plan_, change_,
                      volumes ? &*volumes : nullptr);
  if (scratch_)
    for (FrameStep& s : steps_) s.why = "from scratch";
  runFrame(backend_, ctx, buffers_, steps_, observe);
  plan_ = ctx.plan;
  if (interval > 1 && (!volumes || volumes->due)) {
    volumeScene_ = scene_;
    volumeTriangles_ = triangles_;
    framesSinceUpdate_ = 0;
  } else {
    ++framesSinceUpdate_;
  }
  return steps_;
}

std::string FrameRunner::why() const {
  return scratch_ ? "from scratch" : first_ ? "the first frame" : change_.describe();
}

}  // namespace voxgi
