#include "tests/gl_contexts.h"

#include <map>
#include <memory>

namespace voxgi::test {

gpu::GlContext& glContext(gpu::GlPlatform platform) {
  static std::map<gpu::GlPlatform, std::unique_ptr<gpu::GlContext>> contexts;
  auto& c = contexts[platform];
  if (!c) c = gpu::GlContext::create(platform);
  return *c;
}

}  // namespace voxgi::test
