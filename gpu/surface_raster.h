// Rasterizing the scene's surfaces into stage buffers, shared by the gbuffer and rsm stages: the
// camera geometry's vertices, triangles and materials as storage blocks 0, 1 and 2 (what
// shaders/gbuffer.vert and lpv/rsm.vert pull), and colour targets of one size with a depth test,
// in one or more layers (2D array textures) read back one layer below another.
#pragma once

#include <span>
#include <vector>

#include "common/buffer.h"
#include "common/camera_geometry.h"
#include "gpu/gl.h"

namespace voxgi::gpu {

// A colour target: RGBA32F (the buffer's components read back, the rest dropped) or R32UI.
struct RasterTarget {
  BufferId buffer;
  GLenum format;
};

class SurfaceRaster {
 public:
  SurfaceRaster(const Gl& gl, const Scene& scene, const CameraGeometry& geometry,
                std::span<const RasterTarget> targets, glm::ivec2 size, int layers = 1);
  ~SurfaceRaster();
  SurfaceRaster(const SurfaceRaster&) = delete;
  SurfaceRaster& operator=(const SurfaceRaster&) = delete;

  // Binds the blocks, the framebuffer and the raster state (depth test, no culling) for the
  // program in use.
  void begin();
  // Clears layer `layer` (colour 0, depth 1) and draws every triangle into it.
  void drawLayer(int layer);
  // Restores the default framebuffer and state.
  void end();
  // Target i's texels of every layer, layer after layer along y, as its buffer.
  Buffer read(size_t i) const;

 private:
  const Gl& gl_;
  std::vector<RasterTarget> targets_;
  glm::ivec2 size_;
  int layers_;
  GLsizei vertexCount_;
  GlBuffer vertices_, triangles_, materials_;
  std::vector<GLuint> textures_;  // the targets', then depth
  GLuint fbo_ = 0, vao_ = 0;
};

}  // namespace voxgi::gpu
