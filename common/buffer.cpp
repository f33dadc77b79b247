#include "common/buffer.h"

#include "common/mips.h"
#include "common/parallel.h"
#include "shaders/shared/half_float.h"

#include <stdexcept>

namespace voxgi {
Buffer::Buffer(const BufferSpec& s, glm::ivec3 e)
    : spec(&s),
      extent(e),
      words(size_t(e.x) * size_t(e.y) * size_t(e.z) *
            size_t(s.type == ScalarType::f16 ? s.components / 2 : s.components)) {}

void Buffer::setHalf(size_t element, int component, float value) {
  uint32_t& w = words[element * elementWords() + size_t(component) / 2];
  const uint32_t h = shared::halfBits(shared::roundToHalf(value));
  w = component % 2 == 0 ? (w & 0xffff0000u) | h : (w & 0xffffu) | (h << 16);
}

float Buffer::halfToFloat(uint32_t bits) {
  return shared::halfValue(bits);
}

Words floatWords(const Buffer& b) {
  Words out(b.words.size() * 2);
  halvesToFloats(b.words, std::span(reinterpret_cast<float*>(out.data()), out.size()));
  return out;
}

namespace {
constexpr size_t kConvertChunk = size_t(1) << 16;  // words a task
}  // namespace

void floatsToHalves(std::span<const float> floats, std::span<uint32_t> words) {
  if (floats.size() != 2 * words.size())
    throw std::logic_error("floatsToHalves: two floats a word of halves");
  parallelFor(tbb::blocked_range<size_t>(0, words.size(), kConvertChunk), [&](const auto& r) {
    for (size_t i = r.begin(); i != r.end(); ++i)
      words[i] = shared::halfBits(shared::roundToHalf(floats[2 * i])) |
                 shared::halfBits(shared::roundToHalf(floats[2 * i + 1])) << 16;
  });
}

void halvesToFloats(std::span<const uint32_t> words, std::span<float> floats) {
  if (floats.size() != 2 * words.size())
    throw std::logic_error("halvesToFloats: two floats a word of halves");
  parallelFor(tbb::blocked_range<size_t>(0, words.size(), kConvertChunk), [&](const auto& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      floats[2 * i] = shared::halfValue(words[i] & 0xffffu);
      floats[2 * i + 1] = shared::halfValue(words[i] >> 16);
    }
  });
}

const Buffer& BufferSet::at(BufferId id) const {
  const Buffer* b = find(id);
  if (b == nullptr)
    throw std::logic_error("no buffer " + bufferSpec(id).qualifiedName() +
                           " in the set: no stage before the reader produced it");
  return *b;
}

const Buffer* BufferSet::find(BufferId id) const {
  const auto it = buffers_.find(id);
  return it == buffers_.end() ? nullptr : &it->second;
}

void BufferSet::put(Buffer b) {
  const BufferId id = b.spec->id;
  buffers_.insert_or_assign(id, std::move(b));
}

Buffer BufferSet::take(BufferId id) {
  const auto it = buffers_.find(id);
  if (it == buffers_.end()) return {};
  Buffer b = std::move(it->second);
  buffers_.erase(it);
  return b;
}

double Buffer::value(size_t element, int component) const {
  switch (spec->type) {
    case ScalarType::u32:
      return get<uint32_t>(element, component);
    case ScalarType::i32:
      return get<int32_t>(element, component);
    case ScalarType::f32:
    case ScalarType::f16:
      return get<float>(element, component);
  }
  return 0.0;
}

uint64_t shapeElements(BufferShape shape, int resolution, glm::ivec2 image, int series,
                       glm::ivec2 maps) {
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
    case BufferShape::series:
      return n * n * n * static_cast<uint64_t>(series);
    case BufferShape::maps:
      return uint64_t(maps.x) * uint64_t(maps.x) * uint64_t(maps.y);
    case BufferShape::sparse:
      return 0;  // unknown before the stage counts it
  }
  return 0;
}

glm::ivec3 shapeExtent(BufferShape shape, int resolution, glm::ivec2 image, int series,
                       glm::ivec2 maps) {
  switch (shape) {
    case BufferShape::maps:
      return {maps.x, maps.x * maps.y, 1};
    case BufferShape::volume:
      return glm::ivec3(resolution);
    case BufferShape::series:
      return {resolution, resolution, resolution * series};
    case BufferShape::image:
      return {image.x, image.y, 1};
    default:
      return {static_cast<int>(shapeElements(shape, resolution, image)), 1, 1};
  }
}

}  // namespace voxgi
