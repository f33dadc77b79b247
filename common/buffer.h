// Named, typed buffers that flow between stages. Every element is a 32-bit word (u32, i32 or f32),
// `components` words per voxel or pixel, voxels x-fastest (see common/grid.h).
#pragma once

#include <bit>
#include <cstdlib>
#include <new>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace voxgi {

// Allocates with calloc and leaves default-inserted elements alone, so the pages of a large buffer
// arrive zeroed from the kernel when first touched — by the worker threads that fill the buffer —
// instead of being zero-filled up front by one thread.
template <class T>
struct ZeroedAllocator {
  using value_type = T;
  ZeroedAllocator() = default;
  template <class U>
  ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}
  T* allocate(size_t n) {
    void* p = std::calloc(n, sizeof(T));
    if (p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) noexcept { std::free(p); }
  template <class U>
  void construct(U*) noexcept {}  // default-insertion: keep calloc's zeros
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator&) { return true; }
};
using Words = std::vector<uint32_t, ZeroedAllocator<uint32_t>>;

enum class ScalarType { u32, i32, f32 };
const char* scalarTypeName(ScalarType t);

// Which effect of the plan (common/effect_plan.h) a buffer depends on: without it the buffer is not
// produced.
enum class BufferNeed { always, emission, isotropic, anisotropic, specular, ambient_occlusion };

// How a buffer's elements are laid out (common/pyramid.h has the level offsets):
// volume: N^3 voxels; mips: levels 1..log2(N) of an N^3 volume, level l is (N>>l)^3, one after
// another; mips6: the same levels, each six (N>>l)^3 volumes side by side along x (faces +x, -x,
// +y, -y, +z, -z), so level l is (6(N>>l)) x (N>>l) x (N>>l); image: the camera's pixels, row 0 at
// the top.
enum class BufferShape { volume, mips, mips6, image };

// A buffer as declared in common/stages.inc.
struct BufferSpec {
  std::string_view stage;
  std::string_view name;
  ScalarType type;
  int components;
  BufferShape shape;
  BufferNeed need;
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
  Words words;

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
  // Components 0..2 of an element as floats (f32 buffers).
  glm::vec3 vec3At(size_t element) const {
    return {get<float>(element, 0), get<float>(element, 1), get<float>(element, 2)};
  }
  void setVec3(size_t element, glm::vec3 v) {
    for (int c = 0; c < 3; ++c) set(element, c, v[c]);
  }
  // The element as doubles, for reports and diffs.
  double value(size_t element, int component) const;
};

// Buffers by name; a stage reads its inputs from the set and adds its outputs.
using BufferSet = std::map<std::string, Buffer, std::less<>>;

// Elements of a buffer of `shape` for an N^3 grid or a width x height image.
uint64_t shapeElements(BufferShape shape, int resolution, glm::ivec2 image);
// Elements of a buffer in `shape` as a 3D extent (x-fastest); pyramids are one row.
glm::ivec3 shapeExtent(BufferShape shape, int resolution, glm::ivec2 image);

}  // namespace voxgi
