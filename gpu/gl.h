// OpenGL function table. voxgi never links libGL: OSMesa and EGL each hand out their own entry
// points, so the table is filled from the current context's getProcAddress.
#pragma once

#include <GL/glcorearb.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace voxgi::gpu {

struct Gl {
#define VOXGI_GL(type, name) type name = nullptr;
#include "gpu/gl_functions.inc"

  using ProcLoader = void (*(*)(const char*))();
  // Fills every entry; throws GlUnavailable naming the first one the context lacks.
  void load(ProcLoader getProcAddress);
  // Throws std::runtime_error("what: GL error 0x...") if the GL error flag is set.
  void check(const char* what) const;
};

// No usable GL context (library missing, no 4.5 core, ...): callers may fall back to the CPU.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An object that deletes a GL name when it goes out of scope (deleting name 0 is a no-op in GL).
template <void (*Delete)(const Gl&, GLuint)>
class GlName {
 public:
  GlName(const Gl& gl, GLuint id) : gl_(&gl), id_(id) {}
  GlName(GlName&& other) noexcept : gl_(other.gl_), id_(std::exchange(other.id_, 0u)) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      Delete(*gl_, id_);
      gl_ = other.gl_;
      id_ = std::exchange(other.id_, 0u);
    }
    return *this;
  }
  ~GlName() { Delete(*gl_, id_); }
  GLuint get() const { return id_; }

 private:
  const Gl* gl_;
  GLuint id_;
};

// An immutable buffer object holding `bytes` bytes copied from `data` (at least 1 byte, so that an
// empty input still gives a valid binding).
GLuint createBuffer(const Gl& gl, size_t bytes, const void* data);
// A buffer for a std430 block of a fixed part followed by an unsized array: `header`, then
// `records` (std430 layouts whose C++ structs have no padding beyond the GLSL one).
template <class Header, class Record>
GLuint createBlock(const Gl& gl, const Header& header, const std::vector<Record>& records) {
  std::vector<std::byte> bytes(sizeof header + records.size() * sizeof(Record));
  std::memcpy(bytes.data(), &header, sizeof header);
  if (!records.empty())
    std::memcpy(bytes.data() + sizeof header, records.data(), records.size() * sizeof(Record));
  return createBuffer(gl, bytes.size(), bytes.data());
}
void deleteBuffer(const Gl& gl, GLuint id);
// One dispatch of `count` invocations of the current compute program, 64 a group (its local size),
// two-dimensional past GL's 65535 groups per dimension — a shader's invocation index is
// gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64 * gl_GlobalInvocationID.y — then a barrier
// before storage reads and buffer updates. Nothing for a count of 0.
void dispatchLinear(const Gl& gl, uint64_t count);
void deleteTexture(const Gl& gl, GLuint id);
using GlBuffer = GlName<deleteBuffer>;
using GlTexture = GlName<deleteTexture>;

}  // namespace voxgi::gpu
