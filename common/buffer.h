// Named, typed buffers that flow between stages. Every element is a 32-bit word (u32, i32 or f32),
// `components` words per voxel or pixel, voxels x-fastest (see common/grid.h).
#pragma once

#include <bit>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace voxgi {

enum class ScalarType { u32, i32, f32 };
const char* scalarTypeName(ScalarType t);

// A buffer as declared in common/stages.inc.
struct BufferSpec {
  std::string_view stage;
  std::string_view name;
  ScalarType type;
  int components;
  std::string_view meaning;
};

struct StageSpec {
  std::string_view name;
  std::string_view summary;
};

std::span<const StageSpec> stageSpecs();
std::span<const BufferSpec> bufferSpecs();
// The buffers a stage writes, in declaration order.
std::vector<const BufferSpec*> stageBuffers(std::string_view stage);
const BufferSpec& bufferSpec(std::string_view stage, std::string_view name);
// The stage with this name; nullptr if there is none.
const StageSpec* findStage(std::string_view name);

struct Buffer {
  const BufferSpec* spec = nullptr;
  glm::ivec3 extent{0};
  std::vector<uint32_t> words;

  Buffer() = default;
  Buffer(const BufferSpec& s, glm::ivec3 e);
  size_t elementCount() const { return size_t(extent.x) * size_t(extent.y) * size_t(extent.z); }
  int components() const { return spec->components; }
  template <class T>
  T get(size_t element, int component) const {
    return std::bit_cast<T>(words[element * size_t(spec->components) + size_t(component)]);
  }
  template <class T>
  void set(size_t element, int component, T value) {
    words[element * size_t(spec->components) + size_t(component)] = std::bit_cast<uint32_t>(value);
  }
  // The element as doubles, for reports and diffs.
  double value(size_t element, int component) const;
};

// Buffers by name; a stage reads its inputs from the set and adds its outputs.
using BufferSet = std::map<std::string, Buffer, std::less<>>;

// Bytes `stage` would allocate for its buffers on an extent.
uint64_t stageBufferBytes(std::string_view stage, glm::ivec3 extent);

}  // namespace voxgi
