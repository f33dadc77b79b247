// The technique registry: every technique `voxgi render --technique` runs, from common/stages.inc.
// A technique declares, in its own folder (common/<technique>/): its stages and buffers
// (stages.inc), its parameter table and presets (settings.cpp) and its effect planner (plan.cpp);
// a technique without one of them does not link.
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/buffer.h"
#include "common/effect_plan.h"
#include "common/scene.h"
#include "common/settings_table.h"
#include "common/stage_list.h"
#include "common/sparse_layout.h"

namespace voxgi {

// The buffers of a technique's shading stage that its image's light terms come from
// (common/light_terms.h), each empty where it has none; a technique without indirectDiffuse has
// no terms.
struct LightTermBuffers {
  std::optional<BufferId> directDiffuse, directSpecular, indirectDiffuse, indirectSpecular;
  // Applied to indirectDiffuse only where its compose applies it under these settings.
  std::optional<BufferId> ambientOcclusion;
};

// A technique that runs another one's stages under other defaults (holpv: lpv with 3 SH bands and
// 26 propagation directions), so that a variant is one setting, never a copy of the stages.
struct Variant {
  std::string_view name;
  std::string_view summary;
  std::vector<std::string> defaults;  // "key=value", applied before a scene file's settings
};

struct Technique {
  std::string_view name;
  std::string_view summary;
  BufferId image;                           // the rendered image (linear RGB)
  const std::vector<Param>& (*params)();    // its own keys (the shared ones: sharedParams())
  const std::vector<Preset>& (*presets)();  // "default" first
  // Which of its stages, buffers and effects the scene needs, and why (common/effect_plan.h).
  EffectPlan (*plan)(const Scene& scene, const Settings& settings);
  // Where the elements of its sparse buffers in a run lie as grids (common/sparse_layout.h), for
  // dumps.
  SparseLayouts (*sparseLayouts)(const BufferSet& run, const GridSpec& grid);
  // Which buffers hold its light terms under these settings.
  LightTermBuffers (*lightTerms)(const Settings& settings);
  std::string_view stages;  // whose steps it runs: its own name, or a variant's base
  const std::vector<std::string>* defaults = nullptr;  // a variant's (Variant::defaults)
  std::vector<const StageSpec*> steps() const { return techniqueSteps(stages); }
};

std::span<const Technique> techniques();
// The technique named `name`; throws InputError naming `source` (e.g. "--technique") otherwise.
const Technique& findTechnique(std::string_view name, const std::string& source = "--technique");
// "vct|lpv|...", for help texts and errors.
std::string techniqueNames();

// The per-technique entry points the registry links against (common/<technique>/).
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)            \
  namespace technique {                                                    \
  const std::vector<Param>& params();                                      \
  const std::vector<Preset>& presets();                                    \
  EffectPlan planEffects(const Scene& scene, const Settings& settings);    \
  SparseLayouts sparseLayouts(const BufferSet& run, const GridSpec& grid); \
  LightTermBuffers lightTerms(const Settings& settings);                   \
  const std::vector<Variant>& variants();                                  \
  }
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/stages.inc"

// The settings keys' one scheme: a key is `<stage>.<name>` when one stage reads it
// (propagate.steps, build.seed; voxelize.mode for a technique that runs voxelize), `<owner>.<name>`
// when several of a technique's stages do (lpv.bands, svo.first_step), `plan.mode` for the
// planner, `update.interval` for the planner in time (common/frame_plan.h), and `<kernel>.<name>`
// for the kernels several techniques' stages share, in Settings::vct: these groups
// (tests/settings_test.cpp checks every technique's keys against the scheme).
inline constexpr std::string_view kKernelKeyGroups[] = {
    "emitters", "light", "voxel_shadow", "cones", "shadow", "specular", "ao"};

namespace vct {
// Voxel cone tracing's keys of the kernel `groups` (kKernelKeyGroups): those another technique's
// stages read from Settings::vct too (the octree's cone and light keys, light propagation
// volumes' emitters.mode), so a key means one thing for every technique that takes it.
std::vector<Param> kernelParams(std::initializer_list<std::string_view> groups);
}  // namespace vct

}  // namespace voxgi
