// GPU mip stage: shaders/mip.comp builds the pyramid texture level by level from the uploaded
// radiance volume; the pyramid is read back for the next stage and for `voxgi diff`.
#include "common/mips.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void mip(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, "mip");
  const int n = ctx.scene.grid.resolution;
  const bool isotropic = ctx.settings.mip == MipMode::isotropic;
  const int faces = isotropic ? 1 : 6;
  const BufferSpec& spec = bufferSpec("mip", isotropic ? "radiance_mips" : "radiance_mips6");
  if (mipLevelCount(n) == 0) {  // a 1^3 grid has no levels above the base
    buffers[std::string(spec.name)] = Buffer(spec, shapeExtent(spec.shape, n, {}));
    return;
  }
  GlTexture radiance(gl, uploadVolume(gl, buffers.at("radiance")));
  GlTexture pyramid(gl, createPyramid(gl, n, faces));
  Program program(gl, {"mip.comp"});
  program.set("uFaces", faces);
  program.use();
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const int s = n >> level;
    program.set("uSize", s);
    program.set("uFromBase", level == 1 ? 1 : 0);
    if (level == 1)
      gl.BindImageTexture(0, radiance.get(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    else
      gl.BindImageTexture(0, pyramid.get(), level - 2, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    gl.BindImageTexture(1, pyramid.get(), level - 1, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const auto groups = [](int count) { return static_cast<GLuint>((count + 3) / 4); };
    gl.DispatchCompute(groups(faces * s), groups(s), groups(s));
    gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  gl.check("mip: dispatch");
  buffers[std::string(spec.name)] = readPyramid(gl, pyramid.get(), spec, n, faces);
  gl.check("mip: reading back");
}

}  // namespace voxgi::gpu
