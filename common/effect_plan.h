// The effect plan (docs/effect-plan.md): which stages, buffers and effects a scene needs, decided
// once from the scene and the settings by its technique's planner (common/<technique>/plan.cpp),
// so that a scene pays only for the effects it uses. Stages read the decisions from
// StageContext::plan; `voxgi plan` prints them with the reason for each.
#pragma once

#include <bitset>
#include <string>
#include <string_view>
#include <vector>

#include "common/scene.h"
#include "common/settings.h"
#include "common/stage_list.h"

namespace voxgi {

// One line of the plan: a stage (`stage` set) or an effect, whether it is in, and why.
struct PlanItem {
  std::string name;
  bool in = true;
  std::string why;
  const StageSpec* stage = nullptr;
};

class EffectPlan {
 public:
  bool full = false;  // plan.mode=full: every optional effect is computed
  // Nothing in the scene emits light (Scene::unlit) and plan.mode is auto: every stage that only
  // carries light is out, and the technique's last stage writes the black image alone.
  bool dark = false;
  int seriesLength = 1;         // volumes in a BufferShape::series buffer (lpv: steps + 1)
  glm::ivec2 maps{0};           // BufferShape::maps: x the side of a map, y the map count
  std::vector<PlanItem> items;  // stages in graph order, each followed by its effects

  // A stage of the plan and whether it runs; an effect of it (indented under its stage).
  void stage(StageId id, bool runs, std::string why);
  // A stage that only carries light: as stage(), but out with kDarkReason in a dark plan.
  void lightStage(StageId id, bool runs, std::string why);
  void effect(std::string name, Effect e, bool in, std::string why);
  // An effect decided without a line of its own (its stage's line says why).
  void set(Effect e, bool in) { effects_.set(size_t(e), in); }
  // An item that is neither a stage nor a buffer's effect (cones, shadow lights).
  void note(std::string name, bool in, std::string why);
  // Whether the stage carries a state of its own from frame to frame in a sequence (FrameHistory,
  // common/frame_plan.h) under these settings; only a stage that declares the history among what
  // it reads may (stage_reads::history, common/stages.inc), else std::logic_error.
  void carry(StageId id, bool carries);
  bool carries(StageId id) const { return carries_.test(size_t(id)); }

  // Whether the stage runs (a stage the planner did not list does not).
  bool runs(StageId id) const;
  // Whether the planner decided the stage (listed it, in or out).
  bool decides(StageId id) const;
  // Whether the effect is on (`always` is).
  bool on(Effect e) const { return e == Effect::always || effects_.test(size_t(e)); }
  // Why the stage is out, as `voxgi plan` prints it; empty when it runs.
  std::string whySkipped(StageId id) const;
  // Whether two plans run the same stages with the same effects and shapes (the reasons they
  // give aside): a frame may reuse a stage's buffers only under the same decisions.
  bool sameDecisions(const EffectPlan& other) const;

 private:
  std::bitset<256> effects_;  // by Effect (a uint8_t)
  std::bitset<256> carries_;  // by StageId
};

// Why a dark plan (EffectPlan::dark) leaves a stage out, as `voxgi plan` prints it.
extern const char* const kDarkReason;

// Whether the plan produces the buffer: its stage runs and its effect is on.
bool bufferNeeded(const BufferSpec& spec, const EffectPlan& plan);

// Decides voxelize's dense fixed-point sums (Effect::voxel_sums), as the line under voxelize: kept
// where they are compared or written (settings.inspect), under plan.mode=full, where a later stage
// reads them (`reader` names it; empty for none), or in a sequence (Settings::sequence: the next
// frame's update in part starts from them); otherwise the CPU holds them only in the blocks the
// surface reaches and the GPU in its own memory. Call finishVoxelSums once Effect::emission is
// decided.
void planVoxelSums(EffectPlan& p, const Settings& settings, const std::string& reader);
// The emission volume's sums (Effect::emission_sum): with the other sums and the emission volume.
void finishVoxelSums(EffectPlan& p);

// Refuses a scene with point clouds for a technique that renders triangle meshes only (throws
// InputError naming the scene file and its first cloud), rather than render it without them.
void refusePointClouds(const Scene& scene, std::string_view technique);

// Whether any triangle of `mesh` can be in the camera's view: false only when its bounding box
// lies wholly outside one plane of the view frustum (conservative).
bool meshInView(const Scene& scene, const Mesh& mesh);

}  // namespace voxgi
