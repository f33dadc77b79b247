// Reading a glTF accessor's elements from tinygltf's decoded buffers, each element checked to lie
// inside its buffer view; a fault is an InputError naming the file and accessor.
#pragma once

#include <algorithm>
#include <cstring>
#include <string>

#include <glm/glm.hpp>

#include "common/error.h"
#include "common/scene_io/tinygltf.h"

namespace voxgi {

// Element `i` of an accessor as little-endian bytes: a pointer to its first component, each
// element checked to lie inside its buffer view (a byteStride can reach past what count * size
// does).
class AccessorReader {
 public:
  AccessorReader(const std::string& file, const tinygltf::Model& model, int index,
                 const std::string& field)
      : field_(file + ": accessors[" + std::to_string(index) + "] (" + field + ")") {
    if (index < 0 || size_t(index) >= model.accessors.size()) fail("names no accessor");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) fail("sparse accessors are not supported");
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
      fail("has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) fail("names no buffer");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    componentType = a.componentType;
    components = size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
    const int componentBytes = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (componentBytes <= 0 || components == 0 || components > 16) fail("unknown type");
    elementBytes_ = components * size_t(componentBytes);
    stride_ = view.byteStride != 0 ? view.byteStride : elementBytes_;
    count = a.count;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
      fail("its buffer view runs past its buffer");
    if (count > 0) {
      const long double end = (long double)a.byteOffset + (long double)(count - 1) * stride_ +
                              (long double)elementBytes_;
      if (end > (long double)view.byteLength) fail("runs past the end of its buffer view");
    }
    base_ = data.data() + view.byteOffset + a.byteOffset;
  }
  [[noreturn]] void fail(const std::string& reason) const { throw InputError(field_, "", reason); }
  const unsigned char* element(size_t i) const { return base_ + i * stride_; }
  // Component `c` of element `i` as an unsigned integer (UNSIGNED_BYTE, _SHORT or _INT).
  uint32_t index(size_t i) const {
    const unsigned char* p = element(i);
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return uint32_t(p[0]) | uint32_t(p[1]) << 8;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }
    fail("indices must be unsigned bytes, shorts or ints");
  }
  // Element `i` as a texture coordinate: float, or normalized unsigned byte or short (glTF 2.0
  // §3.7.2.1).
  glm::vec2 texcoord(size_t i) const {
    const unsigned char* p = element(i);
    glm::vec2 uv;
    for (int c = 0; c < 2; ++c) {
      if (componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        std::memcpy(&uv[c], p + 4 * c, 4);
      } else if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        uv[c] = float(p[c]) / 255.0f;
      } else {
        uv[c] = float(uint32_t(p[2 * c]) | uint32_t(p[2 * c + 1]) << 8) / 65535.0f;
      }
    }
    return uv;
  }
  // Component `c` of element `i` as a number: a float, or a normalized integer (glTF 2.0
  // §3.11: signed ones clamped at -1), the types an animation's output may have.
  double number(size_t i, size_t c) const {
    const unsigned char* p = element(i);
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p + 4 * c, 4);
        return f;
      }
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(double(int8_t(p[c])) / 127.0, -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return double(p[c]) / 255.0;
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(double(int16_t(uint16_t(p[2 * c] | p[2 * c + 1] << 8))) / 32767.0, -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return double(uint16_t(p[2 * c] | p[2 * c + 1] << 8)) / 65535.0;
    }
    fail("must be floats or normalized integers");
  }
  glm::vec3 vec3(size_t i) const {
    float v[3];
    std::memcpy(v, element(i), sizeof v);  // glTF is little-endian, as are voxgi's targets
    return {v[0], v[1], v[2]};
  }

  int componentType = 0;
  size_t components = 0;
  size_t count = 0;

 private:
  std::string field_;
  const unsigned char* base_ = nullptr;
  size_t elementBytes_ = 0, stride_ = 0;
};

}  // namespace voxgi
