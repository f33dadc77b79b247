// GPU trace_cones stage: shaders/vct/trace_cones.comp runs the shared cone tracer per pixel on the
// uploaded gbuffer, radiance volume and pyramid; the light terms are read back. At
// cones.diffuse_scale > 1, trace_cones_samples.comp first traces each block's diffuse sample.
#include <vector>

#include "common/cone/cone_trace.h"
#include "common/mips.h"
#include "common/vct/radiance_buffers.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void vct::trace_cones(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::vct_trace_cones);
  const Scene& scene = ctx.scene;
  const int n = scene.grid.resolution;
  const int faces = pyramidFaces(ctx.settings.vct.mip);
  const RadianceBuffers lit = finalRadiance(ctx);
  const ConeTraceSetup setup = prepareConeTrace(ctx);
  const auto& [lights, cones, objects, params] = setup;

  const Buffer& position = buffers.at(BufferId::common_gbuffer_pixel_position);
  const glm::ivec3 extent = position.extent;
  const size_t pixels = size_t(extent.x) * size_t(extent.y);
  GlBuffer lightBlock(gl, createBlock(gl, params, lights));
  GlBuffer coneBlock(gl, createBuffer(gl, cones.size() * sizeof cones[0], cones.data()));
  GlBuffer objectBlock(gl, createBuffer(gl, objects.size() * sizeof objects[0], objects.data()));
  GlBuffer positions(gl, uploadWords(gl, position));
  GlBuffer normals(gl, uploadWords(gl, buffers.at(BufferId::common_gbuffer_pixel_normal)));
  GlBuffer ids(gl, uploadWords(gl, buffers.at(BufferId::common_gbuffer_object_id)));
  GlBuffer terms(gl, createBuffer(gl, pixels * sizeof(shared::PixelTerms), nullptr));
  // One sample per block (one unused record at scale 1: the binding must hold a buffer).
  const int scale = params.diffuseScale;
  const glm::ivec2 blocks = (glm::ivec2(extent) + scale - 1) / scale;
  const size_t sampleCount = scale > 1 ? size_t(blocks.x) * size_t(blocks.y) : 1;
  GlBuffer samples(gl, createBuffer(gl, sampleCount * sizeof(shared::DiffuseSample), nullptr));
  GlTexture radiance(gl, uploadVolume(gl, buffers.at(lit.radiance)));
  GlTexture pyramid(gl, mipLevelCount(n) == 0
                            ? createVolume(gl, 4, glm::ivec3(1))
                            : uploadPyramid(gl, buffers.at(lit.pyramid), n, faces));

  gl.BindTextureUnit(0, radiance.get());
  gl.BindTextureUnit(1, pyramid.get());
  const GLuint bound[] = {lightBlock.get(), coneBlock.get(), objectBlock.get(), positions.get(),
                          normals.get(),    ids.get(),       terms.get(),       samples.get()};
  for (GLuint i = 0; i < 8; ++i) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, bound[i]);
  const auto run = [&](const ShaderSource& shader, glm::ivec2 size) {
    Program program(gl, {&shader});
    program.set("uResolution", n);
    program.set("uWidth", extent.x);
    program.set("uHeight", extent.y);
    program.use();
    gl.DispatchCompute(GLuint((size.x + 7) / 8), GLuint((size.y + 7) / 8), 1);
  };
  if (scale > 1) {
    run(shaders::vct_trace_cones_samples_comp, blocks);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl.check("trace_cones: the blocks' diffuse samples");
  }
  run(shaders::vct_trace_cones_comp, glm::ivec2(extent));
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("trace_cones: dispatch");

  std::vector<shared::PixelTerms> values(pixels);
  gl.GetNamedBufferSubData(terms.get(), 0, GLsizeiptr(values.size() * sizeof(values[0])),
                           values.data());
  gl.check("trace_cones: reading back");
  // Each planned buffer of the stage from its field of the record.
  using enum BufferId;
  using Field = glm::vec4 shared::PixelTerms::*;
  const std::pair<BufferId, Field> fields[] = {
      {vct_trace_cones_direct_diffuse, &shared::PixelTerms::directDiffuse},
      {vct_trace_cones_direct_specular, &shared::PixelTerms::directSpecular},
      {vct_trace_cones_indirect_diffuse, &shared::PixelTerms::indirectDiffuse},
      {vct_trace_cones_indirect_specular, &shared::PixelTerms::indirectSpecular},
      {vct_trace_cones_ambient_occlusion, &shared::PixelTerms::ambientOcclusion}};
  for (const auto& [id, field] : fields) {
    const BufferSpec& spec = bufferSpec(id);
    if (!bufferNeeded(spec, ctx.plan)) continue;
    Buffer out(spec, extent);
    for (size_t e = 0; e < pixels; ++e)
      for (int c = 0; c < spec.components; ++c) out.set(e, c, (values[e].*field)[c]);
    buffers.put(std::move(out));
  }
}

}  // namespace voxgi::gpu
