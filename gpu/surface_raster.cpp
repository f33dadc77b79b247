#include "gpu/surface_raster.h"

#include "shaders/shared/gbuffer_kernel.h"

namespace voxgi::gpu {

SurfaceRaster::SurfaceRaster(const Gl& gl, const Scene& scene, const CameraGeometry& g,
                             std::span<const RasterTarget> targets, glm::ivec2 size, int layers)
    : gl_(gl),
      targets_(targets.begin(), targets.end()),
      size_(size),
      layers_(layers),
      vertexCount_(static_cast<GLsizei>(g.vertices.size())),
      vertices_(gl, createBuffer(gl, g.vertices.size() * sizeof(glm::vec3), g.vertices.data())),
      triangles_(gl, createBuffer(gl, g.triangles.size() * sizeof(shared::SurfaceTriangle),
                                  g.triangles.data())),
      materials_(gl, [&] {
        const std::vector<shared::MaterialData> m = materialData(scene);
        return createBuffer(gl, m.size() * sizeof(shared::MaterialData), m.data());
      }()) {
  const auto count = static_cast<GLsizei>(targets_.size());
  textures_.resize(targets_.size() + 1);
  gl.CreateTextures(GL_TEXTURE_2D_ARRAY, count + 1, textures_.data());
  for (size_t i = 0; i < targets_.size(); ++i)
    gl.TextureStorage3D(textures_[i], 1, targets_[i].format, size.x, size.y, layers);
  gl.TextureStorage3D(textures_.back(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y, layers);
  gl.CreateFramebuffers(1, &fbo_);
  std::vector<GLenum> drawBuffers;
  for (size_t i = 0; i < targets_.size(); ++i)
    drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + GLenum(i));
  gl.NamedFramebufferDrawBuffers(fbo_, count, drawBuffers.data());
  gl.CreateVertexArrays(1, &vao_);
}

SurfaceRaster::~SurfaceRaster() {
  gl_.DeleteVertexArrays(1, &vao_);
  gl_.DeleteFramebuffers(1, &fbo_);
  gl_.DeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
}

void SurfaceRaster::begin() {
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, vertices_.get());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, triangles_.get());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, materials_.get());
  gl_.BindVertexArray(vao_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
  gl_.Viewport(0, 0, size_.x, size_.y);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.Disable(GL_CULL_FACE);
  gl_.Disable(GL_MULTISAMPLE);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void SurfaceRaster::drawLayer(int layer) {
  for (size_t i = 0; i < targets_.size(); ++i)
    gl_.NamedFramebufferTextureLayer(fbo_, GL_COLOR_ATTACHMENT0 + GLenum(i), textures_[i], 0,
                                     layer);
  gl_.NamedFramebufferTextureLayer(fbo_, GL_DEPTH_ATTACHMENT, textures_.back(), 0, layer);
  const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
  const GLuint zeroU[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < targets_.size(); ++i) {
    if (targets_[i].format == GL_R32UI)
      gl_.ClearNamedFramebufferuiv(fbo_, GL_COLOR, GLint(i), zeroU);
    else
      gl_.ClearNamedFramebufferfv(fbo_, GL_COLOR, GLint(i), zero);
  }
  gl_.ClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &one);
  gl_.DrawArrays(GL_TRIANGLES, 0, vertexCount_);
}

void SurfaceRaster::end() {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl_.Disable(GL_DEPTH_TEST);
}

Buffer SurfaceRaster::read(size_t i) const {
  const BufferSpec& spec = bufferSpec(targets_[i].buffer);
  Buffer out(spec, glm::ivec3(size_.x, size_.y * layers_, 1));
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  if (targets_[i].format == GL_R32UI) {
    gl_.GetTextureImage(textures_[i], 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                        static_cast<GLsizei>(out.words.size() * 4), out.words.data());
    return out;
  }
  std::vector<float> rgba(out.elementCount() * 4);
  gl_.GetTextureImage(textures_[i], 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * 4),
                      rgba.data());
  for (size_t e = 0; e < out.elementCount(); ++e)
    for (int c = 0; c < spec.components; ++c) out.set(e, c, rgba[4 * e + size_t(c)]);
  return out;
}

}  // namespace voxgi::gpu
