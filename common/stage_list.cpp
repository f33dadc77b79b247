#include "common/stage_list.h"

#include <array>
#include <stdexcept>

namespace voxgi {
namespace {

#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning) EffectSpec{Effect::effect, #owner, #effect, meaning},
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
constexpr EffectSpec kEffects[] = {
    {Effect::always, "common", "always", "produced whenever its stage runs"},
#include "common/stages.inc"
};

#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary) VOXGI_STAGE_SPEC(owner, stage, reads, summary),
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
constexpr StageSpec kStages[] = {
#include "common/stages.inc"
};

struct Step {
  std::string_view technique, owner, stage;
};
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage) Step{#technique, #owner, #stage},
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
constexpr Step kSteps[] = {
#include "common/stages.inc"
};

#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning) \
  BufferSpec{BufferId::owner##_##stage##_##buffer,                                 \
             StageId::owner##_##stage,                                             \
             #buffer,                                                              \
             ScalarType::type,                                                     \
             components,                                                           \
             BufferShape::shape,                                                   \
             Effect::need,                                                         \
             meaning},
constexpr BufferSpec kBuffers[] = {
#include "common/stages.inc"
};

constexpr bool declared(std::string_view owner, std::string_view stage) {
  for (const StageSpec& s : kStages)
    if (s.owner == owner && s.name == stage) return true;
  return false;
}

// Ids index the tables (a buffer's stage id is declared because it compiled), and no buffer
// name repeats within its stage.
constexpr bool listIsConsistent() {
  for (size_t i = 0; i < std::size(kBuffers); ++i) {
    if (static_cast<size_t>(kBuffers[i].id) != i) return false;
    for (size_t j = 0; j < i; ++j)
      if (kBuffers[j].stage == kBuffers[i].stage && kBuffers[j].name == kBuffers[i].name)
        return false;
  }
  for (size_t i = 0; i < std::size(kStages); ++i)
    if (static_cast<size_t>(kStages[i].id) != i) return false;
  for (size_t i = 0; i < std::size(kEffects); ++i)
    if (static_cast<size_t>(kEffects[i].effect) != i) return false;
  return true;
}
static_assert(listIsConsistent(), "common/stages.inc: a buffer is declared twice");

// Half-float buffers pack two components a word, whole elements a word (common/buffer.h).
constexpr bool halvesPairUp() {
  for (const BufferSpec& b : kBuffers)
    if (b.type == ScalarType::f16 && b.components % 2 != 0) return false;
  return true;
}
static_assert(halvesPairUp(), "common/stages.inc: an f16 buffer has an odd number of components");

// Each step names a declared stage, owned by its technique or shared; a technique runs each of
// its own stages, once, and no two of its steps share a name (bare names are unambiguous within
// a technique).
constexpr bool stepsAreConsistent() {
  for (size_t i = 0; i < std::size(kSteps); ++i) {
    const Step& s = kSteps[i];
    if (!declared(s.owner, s.stage)) return false;
    if (s.owner != s.technique && s.owner != "common") return false;
    for (size_t j = 0; j < i; ++j)
      if (kSteps[j].technique == s.technique && kSteps[j].stage == s.stage) return false;
  }
  for (const StageSpec& stage : kStages) {
    if (stage.owner == "common") continue;
    bool run = false;
    for (const Step& s : kSteps) run |= s.owner == stage.owner && s.stage == stage.name;
    if (!run) return false;
  }
  return true;
}
static_assert(stepsAreConsistent(),
              "common/stages.inc: a VOXGI_STEP names an undeclared stage, another technique's "
              "stage, or a stage twice; or a technique's stage is in none of its steps");

}  // namespace

const char* scalarTypeName(ScalarType t) {
  switch (t) {
    case ScalarType::u32:
      return "u32";
    case ScalarType::i32:
      return "i32";
    case ScalarType::f32:
      return "f32";
    case ScalarType::f16:
      return "f16";
  }
  return "?";
}

const char* bufferShapeName(BufferShape shape) {
  switch (shape) {
    case BufferShape::volume:
      return "volume";
    case BufferShape::mips:
      return "mips";
    case BufferShape::mips6:
      return "mips6";
    case BufferShape::image:
      return "image";
    case BufferShape::series:
      return "series";
    case BufferShape::maps:
      return "maps";
    case BufferShape::sparse:
      return "sparse";
  }
  return "?";
}

std::string StageSpec::qualifiedName() const {
  return shared() ? std::string(name) : std::string(owner) + "/" + std::string(name);
}

const StageSpec& BufferSpec::stageSpec() const {
  return voxgi::stageSpec(stage);
}

std::string BufferSpec::qualifiedName() const {
  return stageSpec().qualifiedName() + "." + std::string(name);
}

std::span<const BufferSpec> bufferSpecs() {
  return kBuffers;
}

const StageSpec& stageSpec(StageId id) {
  return kStages[static_cast<size_t>(id)];
}

const BufferSpec& bufferSpec(BufferId id) {
  return kBuffers[static_cast<size_t>(id)];
}

const EffectSpec& effectSpec(Effect e) {
  return kEffects[static_cast<size_t>(e)];
}

std::vector<const BufferSpec*> stageBuffers(const StageSpec& stage) {
  std::vector<const BufferSpec*> out;
  for (const BufferSpec& b : kBuffers)
    if (b.stage == stage.id) out.push_back(&b);
  return out;
}

const StageSpec* findStage(std::string_view owner, std::string_view name) {
  for (const StageSpec& s : kStages)
    if (s.owner == owner && s.name == name) return &s;
  return nullptr;
}

std::vector<const StageSpec*> techniqueSteps(std::string_view technique) {
  std::vector<const StageSpec*> out;
  for (const Step& s : kSteps)
    if (s.technique == technique) out.push_back(findStage(s.owner, s.stage));
  return out;
}

}  // namespace voxgi
