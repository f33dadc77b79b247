// GPU trace_cones stage: shaders/trace_cones.comp runs the shared cone tracer per pixel on the
// uploaded gbuffer, radiance volume and pyramid; the light terms are read back.
#include <vector>

#include "common/kernel_params.h"
#include "common/mips.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {
namespace {

constexpr int kTerms = 13;  // floats per pixel in the shader's Terms buffer

GLuint wordsBuffer(const Gl& gl, const Buffer& b) {
  return createBuffer(gl, b.words.size() * 4, b.words.data());
}

}  // namespace

void trace_cones(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, "trace_cones");
  const Scene& scene = ctx.scene;
  const int n = scene.grid.resolution;
  const int faces = pyramidFaces(ctx.plan.mip);
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const auto& [lights, cones, objects, params] = setup;

  const Buffer& position = buffers.at("pixel_position");
  const glm::ivec3 extent = position.extent;
  const size_t pixels = size_t(extent.x) * size_t(extent.y);
  GlBuffer lightBlock(gl, createBlock(gl, params, lights));
  GlBuffer coneBlock(gl, createBuffer(gl, cones.size() * sizeof cones[0], cones.data()));
  GlBuffer objectBlock(gl, createBuffer(gl, objects.size() * sizeof objects[0], objects.data()));
  GlBuffer positions(gl, wordsBuffer(gl, position));
  GlBuffer normals(gl, wordsBuffer(gl, buffers.at("pixel_normal")));
  GlBuffer ids(gl, wordsBuffer(gl, buffers.at("object_id")));
  GlBuffer terms(gl, createBuffer(gl, pixels * kTerms * 4, nullptr));
  GlTexture radiance(gl, uploadVolume(gl, buffers.at("radiance")));
  GlTexture pyramid(gl, mipLevelCount(n) == 0
                            ? createVolume(gl, 4, glm::ivec3(1))
                            : uploadPyramid(gl, buffers.at(pyramidName(ctx.plan.mip)), n, faces));

  Program program(gl, {"trace_cones.comp"});
  program.set("uResolution", n);
  program.set("uWidth", extent.x);
  program.set("uHeight", extent.y);
  program.use();
  gl.BindTextureUnit(0, radiance.get());
  gl.BindTextureUnit(1, pyramid.get());
  const GLuint blocks[] = {lightBlock.get(), coneBlock.get(), objectBlock.get(), positions.get(),
                           normals.get(),    ids.get(),       terms.get()};
  for (GLuint i = 0; i < 7; ++i) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, blocks[i]);
  gl.DispatchCompute(GLuint((extent.x + 7) / 8), GLuint((extent.y + 7) / 8), 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("trace_cones: dispatch");

  std::vector<float> values(pixels * kTerms);
  gl.GetNamedBufferSubData(terms.get(), 0, GLsizeiptr(values.size() * 4), values.data());
  gl.check("trace_cones: reading back");
  // Term offsets in the 13 floats, per buffer of the stage.
  const std::pair<const char*, int> layout[] = {{"direct_diffuse", 0},
                                                {"direct_specular", 3},
                                                {"indirect_diffuse", 6},
                                                {"indirect_specular", 9},
                                                {"ambient_occlusion", 12}};
  for (const auto& [name, offset] : layout) {
    const BufferSpec& spec = bufferSpec("trace_cones", name);
    if (!bufferNeeded(spec, ctx.plan)) continue;
    Buffer out(spec, extent);
    for (size_t e = 0; e < pixels; ++e)
      for (int c = 0; c < spec.components; ++c)
        out.set(e, c, values[e * kTerms + size_t(offset + c)]);
    buffers[std::string(name)] = std::move(out);
  }
}

}  // namespace voxgi::gpu
