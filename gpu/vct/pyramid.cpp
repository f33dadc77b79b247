#include "gpu/vct/pyramid.h"

#include "common/mips.h"
#include "gpu/program.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

GlTexture buildPyramid(const Gl& gl, GLuint radiance, int n, int faces) {
  GlTexture pyramid(gl, createPyramid(gl, n, faces));
  Program program(gl, {&shaders::vct_mip_comp});
  program.set("uFaces", faces);
  program.use();
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const int s = n >> level;
    program.set("uSize", s);
    program.set("uFromBase", level == 1 ? 1 : 0);
    if (level == 1)
      gl.BindImageTexture(0, radiance, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    else
      gl.BindImageTexture(0, pyramid.get(), level - 2, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl.BindImageTexture(1, pyramid.get(), level - 1, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto groups = [](int count) { return static_cast<GLuint>((count + 3) / 4); };
    gl.DispatchCompute(groups(faces * s), groups(s), groups(s));
    gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  gl.check("mip: dispatch");
  return pyramid;
}

}  // namespace voxgi::gpu
