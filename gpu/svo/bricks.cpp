#include "gpu/svo/bricks.h"

#include <algorithm>

#include "gpu/program.h"
#include "gpu/svo/svo_volumes.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu::svo {

GLuint completeBricks(const Gl& gl, GLuint nodes, GLuint tileRecords, GLuint interior,
                      size_t tileCount, int faces) {
  const size_t texels = tileCount * shared::kBrickTexels;
  const GLuint bricks =
      createBuffer(gl, halvesBytes(std::max<size_t>(texels, 1) * size_t(faces)), nullptr);
  Program program(gl, {&shaders::svo_bricks_comp});
  program.use();
  program.set("uCount", unsigned(texels));
  program.set("uFaces", unsigned(faces));
  const GLuint blocks[] = {nodes, tileRecords, interior, bricks};
  for (GLuint b = 0; b < 4; ++b) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  dispatchLinear(gl, texels);
  gl.check("bricks");
  return bricks;
}

}  // namespace voxgi::gpu::svo
