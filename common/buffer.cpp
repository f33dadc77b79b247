#include "common/buffer.h"

#include <array>
#include <stdexcept>

namespace voxgi {
namespace {

#define VOXGI_STAGE(stage, summary) StageSpec{#stage, summary},
constexpr std::array kStages{
#include "common/stages.inc"
};
#undef VOXGI_STAGE

#define VOXGI_BUFFER(stage, name, type, components, need, meaning) \
  BufferSpec{#stage, #name, ScalarType::type, components, BufferNeed::need, meaning},
constexpr std::array kBuffers{
#include "common/stages.inc"
};
#undef VOXGI_BUFFER

}  // namespace

const char* scalarTypeName(ScalarType t) {
  switch (t) {
    case ScalarType::u32:
      return "u32";
    case ScalarType::i32:
      return "i32";
    case ScalarType::f32:
      return "f32";
  }
  return "?";
}

std::span<const StageSpec> stageSpecs() {
  return kStages;
}
std::span<const BufferSpec> bufferSpecs() {
  return kBuffers;
}

std::vector<const BufferSpec*> stageBuffers(std::string_view stage) {
  std::vector<const BufferSpec*> out;
  for (const BufferSpec& b : kBuffers)
    if (b.stage == stage) out.push_back(&b);
  return out;
}

const BufferSpec& bufferSpec(std::string_view stage, std::string_view name) {
  for (const BufferSpec& b : kBuffers)
    if (b.stage == stage && b.name == name) return b;
  throw std::out_of_range("no buffer " + std::string(stage) + "." + std::string(name));
}

const StageSpec* findStage(std::string_view name) {
  for (const StageSpec& s : kStages)
    if (s.name == name) return &s;
  return nullptr;
}

Buffer::Buffer(const BufferSpec& s, glm::ivec3 e)
    : spec(&s), extent(e), words(size_t(e.x) * size_t(e.y) * size_t(e.z) * size_t(s.components)) {}

double Buffer::value(size_t element, int component) const {
  switch (spec->type) {
    case ScalarType::u32:
      return get<uint32_t>(element, component);
    case ScalarType::i32:
      return get<int32_t>(element, component);
    case ScalarType::f32:
      return get<float>(element, component);
  }
  return 0.0;
}

uint64_t stageBufferBytes(std::string_view stage, glm::ivec3 extent, bool emissive) {
  uint64_t words = 0;
  for (const BufferSpec* b : stageBuffers(stage))
    if (b->need == BufferNeed::always || emissive) words += uint64_t(b->components);
  return words * 4u * uint64_t(extent.x) * uint64_t(extent.y) * uint64_t(extent.z);
}

}  // namespace voxgi
