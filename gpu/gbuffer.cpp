// GPU gbuffer stage: rasterizes the voxel-local triangles into float and integer render targets
// (one per buffer) with a depth test, then reads them back. The projection flips y so GL row 0 is
// image row 0, and pixel centres are the CPU rays' (common/camera_geometry.h).
#include <vector>

#include "common/camera_geometry.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"
#include "shaders/shared/gbuffer_kernel.h"

namespace voxgi::gpu {
namespace {

struct Target {
  BufferId buffer;
  GLenum format;
};
// Colour attachment i holds Targets[i]; float targets are RGBA32F (extra channels dropped).
constexpr Target kTargets[] = {{BufferId::common_gbuffer_pixel_position, GL_RGBA32F},
                               {BufferId::common_gbuffer_pixel_normal, GL_RGBA32F},
                               {BufferId::common_gbuffer_pixel_albedo, GL_RGBA32F},
                               {BufferId::common_gbuffer_pixel_specular, GL_RGBA32F},
                               {BufferId::common_gbuffer_pixel_emission, GL_RGBA32F},
                               {BufferId::common_gbuffer_object_id, GL_R32UI},
                               {BufferId::common_gbuffer_primitive_id, GL_R32UI}};
constexpr int kTargetCount = 7;

}  // namespace

void common::gbuffer(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::common_gbuffer);
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const CameraRays& cam = g.camera;
  const int w = cam.width, h = cam.height;
  std::vector<shared::MaterialData> materials;
  for (const Material& m : ctx.scene.materials)
    materials.push_back({glm::vec4(m.albedo, 0.0f), glm::vec4(m.specular, m.shininess),
                         glm::vec4(m.emission, 0.0f)});
  GlBuffer vertices(gl, createBuffer(gl, g.vertices.size() * sizeof(glm::vec3), g.vertices.data()));
  GlBuffer triangles(
      gl, createBuffer(gl, g.triangles.size() * sizeof(SurfaceTriangle), g.triangles.data()));
  GlBuffer materialBlock(
      gl, createBuffer(gl, materials.size() * sizeof(shared::MaterialData), materials.data()));

  std::vector<GLuint> textures(kTargetCount + 1);
  gl.CreateTextures(GL_TEXTURE_2D, kTargetCount + 1, textures.data());
  GLuint fbo = 0;
  gl.CreateFramebuffers(1, &fbo);
  GLenum drawBuffers[kTargetCount];
  for (int i = 0; i < kTargetCount; ++i) {
    gl.TextureStorage2D(textures[size_t(i)], 1, kTargets[i].format, w, h);
    gl.NamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + GLenum(i), textures[size_t(i)], 0);
    drawBuffers[i] = GL_COLOR_ATTACHMENT0 + GLenum(i);
  }
  gl.TextureStorage2D(textures[kTargetCount], 1, GL_DEPTH_COMPONENT32F, w, h);
  gl.NamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, textures[kTargetCount], 0);
  gl.NamedFramebufferDrawBuffers(fbo, kTargetCount, drawBuffers);
  const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
  const GLuint zeroU[4] = {0, 0, 0, 0};
  for (int i = 0; i < kTargetCount; ++i) {
    if (kTargets[i].format == GL_R32UI)
      gl.ClearNamedFramebufferuiv(fbo, GL_COLOR, i, zeroU);
    else
      gl.ClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
  }
  gl.ClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &one);

  Program program(gl, {&shaders::gbuffer_vert, &shaders::gbuffer_frag});
  program.set("uViewProjection", cam.viewProjection(1e-2f, g.farPlane));
  program.set("uForward", cam.forward);
  program.set("uRight", cam.right);
  program.set("uUp", cam.up);
  program.set("uTanHalfFov", cam.tanHalfFov);
  program.set("uAspect", cam.aspect);
  program.set("uSize", glm::vec2(float(w), float(h)));
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertices.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, triangles.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, materialBlock.get());
  GLuint vao = 0;
  gl.CreateVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.Viewport(0, 0, w, h);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_MULTISAMPLE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(g.vertices.size()));
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.Disable(GL_DEPTH_TEST);
  gl.DeleteVertexArrays(1, &vao);
  gl.check("gbuffer: rasterizing");

  const glm::ivec3 extent(w, h, 1);
  std::vector<float> rgba(size_t(w) * size_t(h) * 4);
  for (int i = 0; i < kTargetCount; ++i) {
    const BufferSpec& spec = bufferSpec(kTargets[i].buffer);
    if (!bufferNeeded(spec, ctx.plan)) continue;
    Buffer out(spec, extent);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    if (kTargets[i].format == GL_R32UI) {
      gl.GetTextureImage(textures[size_t(i)], 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                         static_cast<GLsizei>(out.words.size() * 4), out.words.data());
    } else {
      gl.GetTextureImage(textures[size_t(i)], 0, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(rgba.size() * 4), rgba.data());
      for (size_t e = 0; e < out.elementCount(); ++e)
        for (int c = 0; c < spec.components; ++c) out.set(e, c, rgba[4 * e + size_t(c)]);
    }
    buffers.put(std::move(out));
  }
  gl.DeleteFramebuffers(1, &fbo);
  gl.DeleteTextures(kTargetCount + 1, textures.data());
  gl.check("gbuffer: reading back");
}

}  // namespace voxgi::gpu
