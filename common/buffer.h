// Typed buffers that flow between stages. A component is a 32-bit word (u32, i32 or f32) or half
// of one (f16: two halves a word, the low half first), `components` of them per voxel or pixel,
// voxels x-fastest (see common/grid.h).
#pragma once

#include <bit>
#include <cstdlib>
#include <new>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "common/stage_list.h"

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

struct Buffer {
  const BufferSpec* spec = nullptr;
  glm::ivec3 extent{0};
  Words words;

  Buffer() = default;
  Buffer(const BufferSpec& s, glm::ivec3 e);
  Buffer(BufferId id, glm::ivec3 e) : Buffer(bufferSpec(id), e) {}
  size_t elementCount() const { return size_t(extent.x) * size_t(extent.y) * size_t(extent.z); }
  int components() const { return spec->components; }
  bool halves() const { return spec->type == ScalarType::f16; }
  // Words an element takes: its components, or half as many for f16.
  size_t elementWords() const { return size_t(halves() ? spec->components / 2 : spec->components); }
  // get<float> of an f16 buffer is the half's exact value; get<uint32_t> of one is its 16 bits.
  template <class T>
  T get(size_t element, int component) const {
    if (halves()) {
      const uint32_t bits = halfBitsAt(element, component);
      if constexpr (std::is_same_v<T, float>)
        return halfToFloat(bits);
      else
        return T(bits);
    }
    return std::bit_cast<T>(words[element * size_t(spec->components) + size_t(component)]);
  }
  // set<float> of an f16 buffer stores the nearest half (ties to even, as the GPU's packing in
  // shaders/shared/half_float.h).
  template <class T>
  void set(size_t element, int component, T value) {
    if constexpr (std::is_same_v<T, float>)
      if (halves()) return setHalf(element, component, value);
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
  // A component's bits as stored: its word, or its 16 bits of an f16 buffer's word.
  uint32_t bitsAt(size_t element, int component) const {
    return halves() ? halfBitsAt(element, component)
                    : words[element * size_t(spec->components) + size_t(component)];
  }

 private:
  uint32_t halfBitsAt(size_t element, int component) const {
    const uint32_t w = words[element * elementWords() + size_t(component) / 2];
    return component % 2 == 0 ? w & 0xffffu : w >> 16;
  }
  void setHalf(size_t element, int component, float value);
  static float halfToFloat(uint32_t bits);
};

// Components 0..2 of element e of `b`, or 0 where the plan did not produce the buffer (nullptr).
inline glm::vec3 vec3AtOr0(const Buffer* b, size_t e) {
  return b == nullptr ? glm::vec3(0.0f) : b->vec3At(e);
}

// The components of an f16 buffer as f32 words, each half widened exactly: for readers that work
// in floats.
Words floatWords(const Buffer& b);
// An f16 buffer's words from floats and back, in bulk (two values a word, the low half first;
// `floats` has twice as many values as `words`): each value rounded to the nearest half, and each
// half widened exactly, as Buffer::set and get convert one component.
void floatsToHalves(std::span<const float> floats, std::span<uint32_t> words);
void halvesToFloats(std::span<const uint32_t> words, std::span<float> floats);

// The buffers of one run, each under its own declaration (stage and name): bounce's radiance
// never replaces light_voxels'. A stage reads its inputs with at() or find() and adds its outputs
// with put(); iteration follows the declaration order of common/stages.inc.
class BufferSet {
 public:
  // Throws std::logic_error naming the buffer when the set does not hold it (a stage read an
  // input that no stage before it produced).
  const Buffer& at(BufferId id) const;
  const Buffer* find(BufferId id) const;
  bool contains(BufferId id) const { return buffers_.count(id) != 0; }
  // Adds or replaces the buffer under its spec's id.
  void put(Buffer b);
  // Moves the buffer out of the set (an empty Buffer if absent), for a stage that rebuilds it in
  // place and puts it back.
  Buffer take(BufferId id);
  size_t size() const { return buffers_.size(); }
  auto begin() const { return buffers_.begin(); }
  auto end() const { return buffers_.end(); }

 private:
  std::map<BufferId, Buffer> buffers_;
};

// Elements of a buffer of `shape` for an N^3 grid or a width x height image (`series` volumes for
// the series shape, maps.y maps of maps.x^2 texels for the maps shape; 0 for a sparse buffer,
// whose stage checks its own memory).
uint64_t shapeElements(BufferShape shape, int resolution, glm::ivec2 image, int series = 1,
                       glm::ivec2 maps = {});
// Elements of a buffer in `shape` as a 3D extent (x-fastest); pyramids are one row.
glm::ivec3 shapeExtent(BufferShape shape, int resolution, glm::ivec2 image, int series = 1,
                       glm::ivec2 maps = {});

}  // namespace voxgi
