// GPU compose stage: shaders/compose.comp runs the shared final-colour kernel per pixel on the
// gbuffer's materials and trace_cones' terms, packed per pixel on the host.
#include <vector>

#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"

namespace voxgi::gpu {

void compose(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, "compose");
  const Buffer& objectId = buffers.at("object_id");
  const size_t pixels = objectId.elementCount();
  // The shader's Inputs layout: 7 rgb terms then AO; absent buffers (no glossy, emissive
  // material or AO) stay 0, and so does AO unless ao.mode=on (plan.mode=full computes it anyway).
  constexpr size_t kInputs = 22;
  const char* rgbTerms[] = {"pixel_albedo",     "pixel_specular",  "pixel_emission",
                            "direct_diffuse",   "direct_specular", "indirect_diffuse",
                            "indirect_specular"};
  std::vector<float> inputs(pixels * kInputs, 0.0f);
  for (size_t t = 0; t < 7; ++t) {
    const auto it = buffers.find(rgbTerms[t]);
    if (it == buffers.end()) continue;
    for (size_t e = 0; e < pixels; ++e)
      for (int c = 0; c < 3; ++c)
        inputs[e * kInputs + 3 * t + size_t(c)] = it->second.get<float>(e, c);
  }
  if (const auto ao = buffers.find("ambient_occlusion");
      ao != buffers.end() && ctx.settings.ambientOcclusion == AmbientOcclusion::on)
    for (size_t e = 0; e < pixels; ++e) inputs[e * kInputs + 21] = ao->second.get<float>(e, 0);

  GlBuffer ids(gl, createBuffer(gl, objectId.words.size() * 4, objectId.words.data()));
  GlBuffer inputBlock(gl, createBuffer(gl, inputs.size() * 4, inputs.data()));
  GlBuffer color(gl, createBuffer(gl, pixels * 3 * 4, nullptr));
  Program program(gl, {"compose.comp"});
  program.set("uPixels", int(pixels));
  program.set("uBackground", ctx.scene.background);
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ids.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, inputBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, color.get());
  gl.DispatchCompute(GLuint((pixels + 63) / 64), 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("compose: dispatch");
  Buffer out(bufferSpec("compose", "color"), objectId.extent);
  gl.GetNamedBufferSubData(color.get(), 0, GLsizeiptr(pixels * 3 * 4), out.words.data());
  gl.check("compose: reading back");
  buffers["color"] = std::move(out);
}

}  // namespace voxgi::gpu
