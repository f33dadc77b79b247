#include "common/buffer.h"

#include "common/mips.h"

#include <array>
#include <stdexcept>

namespace voxgi {
namespace {

#define VOXGI_STAGE(stage, summary) StageSpec{#stage, summary},
constexpr std::array kStages{
#include "common/stages.inc"
};
#undef VOXGI_STAGE

#define VOXGI_BUFFER(stage, name, type, components, shape, need, meaning)                \
  BufferSpec{#stage,           #name,  ScalarType::type, components, BufferShape::shape, \
             BufferNeed::need, meaning},
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

uint64_t shapeElements(BufferShape shape, int resolution, glm::ivec2 image) {
  const auto n = static_cast<uint64_t>(resolution);
  const int levels = mipLevelCount(resolution);
  switch (shape) {
    case BufferShape::volume:
      return n * n * n;
    case BufferShape::mips:
      return mipLevelOffset(resolution, levels + 1, 1);
    case BufferShape::mips6:
      return mipLevelOffset(resolution, levels + 1, 6);
    case BufferShape::image:
      return uint64_t(image.x) * uint64_t(image.y);
  }
  return 0;
}

glm::ivec3 shapeExtent(BufferShape shape, int resolution, glm::ivec2 image) {
  switch (shape) {
    case BufferShape::volume:
      return glm::ivec3(resolution);
    case BufferShape::image:
      return {image.x, image.y, 1};
    default:
      return {static_cast<int>(shapeElements(shape, resolution, image)), 1, 1};
  }
}

}  // namespace voxgi
