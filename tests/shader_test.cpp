// The embedded shaders: they compile and link on both platforms, the std430 layout of the shared
// VoxelTriangle matches the C++ struct, and compile errors point at file:line.
#include <cstddef>

#include <gtest/gtest.h>

#include "gpu/program.h"
#include "shaders/shader_source.h"
#include "shaders/shared/voxelize_layout.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

TEST(Shaders, EveryProgramLinksOnBothPlatforms) {
  for (gpu::GlPlatform p : {gpu::GlPlatform::osmesa, gpu::GlPlatform::egl}) {
    gpu::GlContext& context = glContext(p);
    context.makeCurrent();
    EXPECT_NO_THROW(gpu::Program(
        context.gl(), {&shaders::voxelize_vert, &shaders::voxelize_geom, &shaders::voxelize_frag}));
    EXPECT_NO_THROW(gpu::Program(context.gl(), {&shaders::voxelize_antialiased_comp}));
    EXPECT_NO_THROW(gpu::Program(context.gl(), {&shaders::voxelize_resolve_comp}));
  }
}

TEST(Shaders, VoxelTriangleLayoutMatchesCpp) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  context.makeCurrent();
  const gpu::Gl& gl = context.gl();
  const gpu::Program program(gl, {&shaders::voxelize_antialiased_comp});
  auto query = [&](const char* variable, GLenum property) {
    const GLuint index = gl.GetProgramResourceIndex(program.id(), GL_BUFFER_VARIABLE, variable);
    EXPECT_NE(index, GL_INVALID_INDEX) << variable;
    GLint value = -1;
    gl.GetProgramResourceiv(program.id(), GL_BUFFER_VARIABLE, index, 1, &property, 1, nullptr,
                            &value);
    return value;
  };
  using shared::VoxelTriangle;
  EXPECT_EQ(query("triangles[0].v0", GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(VoxelTriangle)));
  EXPECT_EQ(query("triangles[0].v0", GL_OFFSET), GLint(offsetof(VoxelTriangle, v0)));
  EXPECT_EQ(query("triangles[0].v1", GL_OFFSET), GLint(offsetof(VoxelTriangle, v1)));
  EXPECT_EQ(query("triangles[0].v2", GL_OFFSET), GLint(offsetof(VoxelTriangle, v2)));
  EXPECT_EQ(query("triangles[0].albedo", GL_OFFSET), GLint(offsetof(VoxelTriangle, albedo)));
  EXPECT_EQ(query("triangles[0].normal", GL_OFFSET), GLint(offsetof(VoxelTriangle, normal)));
  EXPECT_EQ(query("triangles[0].emission", GL_OFFSET), GLint(offsetof(VoxelTriangle, emission)));
  EXPECT_EQ(query("triangles[0].info", GL_OFFSET), GLint(offsetof(VoxelTriangle, info)));
}

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
