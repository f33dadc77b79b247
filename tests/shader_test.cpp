// Compile errors of the embedded shaders point at file:line (tests/layout_test.cpp links every
// program and checks the std430 layouts).
#include <gtest/gtest.h>

#include "gpu/program.h"
#include "shaders/shader_source.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

TEST(Shaders, CompileErrorsNameTheFileAndLine) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  context.makeCurrent();
  const ShaderSource& source = shaders::voxelize_frag;
  ASSERT_GE(source.files.size(), 2u);
  std::string text(source.text);
  // An error on line 42 of the first included file (source-string number 1).
  const size_t afterVersion = text.find('\n') + 1;
  text.insert(afterVersion, "#line 42 1\nthis is not GLSL;\n#line 2 0\n");
  try {
    gpu::compileShader(context.gl(), source, text);
    FAIL() << "broken shader compiled";
  } catch (const gpu::ShaderError& e) {
    const std::string expected = std::string(source.files[1]) + ":42";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(Shaders, LogMappingHandlesMesaAndNvidiaFormats) {
  const ShaderSource& source = shaders::voxelize_frag;
  const std::string file = std::string(source.files[1]);
  EXPECT_NE(mapShaderLog(source, "1:12(5): error: x").find(file + ":12"), std::string::npos);
  EXPECT_NE(mapShaderLog(source, "1(12) : error C0000: x").find(file + ":12"), std::string::npos);
  EXPECT_EQ(mapShaderLog(source, "99:12(5): error").find(file), std::string::npos);
}

}  // namespace
}  // namespace voxgi::test
