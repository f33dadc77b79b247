// common/stages.inc as C++: the effects, stages, technique steps and buffers every part of voxgi
// refers to, as constexpr tables and typed ids. A buffer is named in code by its BufferId
// (BufferId::vct_light_voxels_radiance), so a misspelt or undeclared buffer does not compile.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace voxgi {

// f16: IEEE half floats, two a 32-bit word (the low half first); such a buffer has an even
// number of components, so that no element shares a word with the next (common/buffer.h).
enum class ScalarType { u32, i32, f32, f16 };
const char* scalarTypeName(ScalarType t);

// How a buffer's elements are laid out (common/mips.h has the level offsets):
// volume: N^3 voxels; mips: levels 1..log2(N) of an N^3 volume, level l is (N>>l)^3, one after
// another; mips6: the same levels, each six (N>>l)^3 volumes side by side along x (faces +x, -x,
// +y, -y, +z, -z), so level l is (6(N>>l)) x (N>>l) x (N>>l); image: the camera's pixels, row 0 at
// the top; series: EffectPlan::seriesLength N^3 volumes one after another (N x N x N*length);
// maps: EffectPlan::maps square images (texels of a shadow map's views, row 0 at the top) one
// below another (R x R*count); sparse: as many elements as the stage allocates (an octree's pools,
// common/svo/stages.inc), one row, its memory checked by the stage from the counts it finds.
enum class BufferShape { volume, mips, mips6, image, series, maps, sparse };
const char* bufferShapeName(BufferShape shape);  // as common/stages.inc spells it

// An effect of the plan (common/effect_plan.h) a buffer may depend on; `always` for none.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning) effect,
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
enum class Effect : uint8_t {
  always,
#include "common/stages.inc"
};

// Every declared stage: StageId::<owner>_<stage>, in declaration order.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary) owner##_##stage,
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
enum class StageId : uint16_t {
#include "common/stages.inc"
};

// Every declared buffer: BufferId::<owner>_<stage>_<buffer>, in declaration order.
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning) \
  owner##_##stage##_##buffer,
enum class BufferId : uint16_t {
#include "common/stages.inc"
};

// What a stage reads besides the settings, the grid, the materials and the textures (which stay
// fixed through a sequence), declared with it: VOXGI_STAGE's `reads` (common/stages.inc), as
// `geometry | lights | buffers`. The planner in time (common/frame_plan.h) reruns a stage in a
// frame where one of them changed.
namespace stage_reads {
enum Input : unsigned {
  geometry = 1,  // mesh positions, point clouds
  // the scene's lights, and a mesh's emitters where they light as area lights (emitters.mode), so
  // a stage that reads lights reads the geometry too
  lights = 2,
  camera = 4,
  buffers = 8,  // buffers of the stages before it
  // its own state from the frame before (FrameHistory), where its plan says it carries one
  // (EffectPlan::carries)
  history = 16,
};
constexpr unsigned kScene = geometry | lights | camera;  // the scene's parts that can change
constexpr unsigned kAll = kScene | buffers | history;
}  // namespace stage_reads

struct EffectSpec {
  Effect effect;
  std::string_view owner, name, meaning;
};

struct StageSpec {
  StageId id;
  std::string_view owner;  // the technique, or "common" for a stage several techniques run
  std::string_view name;
  std::string_view summary;
  unsigned reads;  // stage_reads bits
  bool shared() const { return owner == "common"; }
  // How commands and reports name it: "voxelize" for a shared stage, "vct/trace_cones" otherwise.
  std::string qualifiedName() const;
};

// A stage's entry in the table, from its declaration (VOXGI_STAGE's arguments, in namespace voxgi):
// `reads` is an expression of stage_reads' names, and one that reads nothing, or something else,
// stops the build naming the stage (tests/build_guards/stage_without_reads.cpp).
#define VOXGI_STAGE_SPEC(owner, stage, reads, summary)                               \
  StageSpec {                                                                        \
    StageId::owner##_##stage, #owner, #stage, summary, [] {                          \
      using namespace stage_reads;                                                   \
      constexpr unsigned bits = reads;                                               \
      static_assert(bits != 0 && (bits & ~kAll) == 0,                                \
                    "stage " #owner "/" #stage                                       \
                    " must declare what it reads (stage_reads, common/stages.inc)"); \
      return bits;                                                                   \
    }()                                                                              \
  }

struct BufferSpec {
  BufferId id;
  StageId stage;
  std::string_view name;
  ScalarType type;
  int components;
  BufferShape shape;
  Effect need;
  std::string_view meaning;
  const StageSpec& stageSpec() const;
  std::string qualifiedName() const;  // "voxelize.opacity", "vct/light_voxels.radiance"
};

std::span<const BufferSpec> bufferSpecs();
const StageSpec& stageSpec(StageId id);
const BufferSpec& bufferSpec(BufferId id);
const EffectSpec& effectSpec(Effect e);
// The buffers a stage writes, in declaration order.
std::vector<const BufferSpec*> stageBuffers(const StageSpec& stage);
// The stage `owner`/`name` ("common" for shared stages); nullptr if there is none.
const StageSpec* findStage(std::string_view owner, std::string_view name);
// The stages `technique` runs, in graph order.
std::vector<const StageSpec*> techniqueSteps(std::string_view technique);

}  // namespace voxgi
