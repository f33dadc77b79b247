// GPU compose stage: shaders/vct/compose.comp runs the shared final-colour kernel per pixel on the
// gbuffer's materials and trace_cones' terms, packed per pixel on the host.
#include <optional>
#include <vector>

#include "common/technique.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/volumes.h"
#include "shaders/shared/compose.h"

namespace voxgi::gpu {

void vct::compose(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  const Gl& gl = beginStage(context, ctx, StageId::vct_compose);
  using enum BufferId;
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  const size_t pixels = objectId.elementCount();
  // Absent buffers (no glossy, emissive material or AO) leave their terms 0, and so is AO unless
  // ao.mode=on (plan.mode=full computes it anyway).
  using Field = glm::vec4 shared::ComposeInput::*;
  using Input = shared::ComposeInput;
  const std::pair<BufferId, Field> terms[] = {
      {common_gbuffer_pixel_albedo, &Input::albedo},
      {common_gbuffer_pixel_specular, &Input::specular},
      {common_gbuffer_pixel_emission, &Input::emission},
      {vct_trace_cones_direct_diffuse, &Input::directDiffuse},
      {vct_trace_cones_direct_specular, &Input::directSpecular},
      {vct_trace_cones_indirect_diffuse, &Input::indirectDiffuse},
      {vct_trace_cones_indirect_specular, &Input::indirectSpecular}};
  std::vector<Input> inputs(pixels, Input{});
  for (const auto& [id, field] : terms) {
    const Buffer* term = buffers.find(id);
    if (term == nullptr) continue;
    for (size_t e = 0; e < pixels; ++e) inputs[e].*field = glm::vec4(term->vec3At(e), 0.0f);
  }
  // AO only where the technique's light terms apply it, as on the CPU.
  const std::optional<BufferId> aoId = ctx.technique.lightTerms(ctx.settings).ambientOcclusion;
  if (const Buffer* ao = aoId ? buffers.find(*aoId) : nullptr; ao != nullptr)
    for (size_t e = 0; e < pixels; ++e) inputs[e].ambientOcclusion = ao->get<float>(e, 0);

  GlBuffer ids(gl, createBuffer(gl, objectId.words.size() * 4, objectId.words.data()));
  GlBuffer inputBlock(gl, createBuffer(gl, inputs.size() * sizeof(Input), inputs.data()));
  GlBuffer color(gl, createBuffer(gl, pixels * 3 * 4, nullptr));
  Program program(gl, {&shaders::vct_compose_comp});
  program.set("uPixels", int(pixels));
  program.set("uBackground", ctx.scene.background);
  program.use();
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ids.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, inputBlock.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, color.get());
  gl.DispatchCompute(GLuint((pixels + 63) / 64), 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("compose: dispatch");
  Buffer out(BufferId::vct_compose_color, objectId.extent);
  gl.GetNamedBufferSubData(color.get(), 0, GLsizeiptr(pixels * 3 * 4), out.words.data());
  gl.check("compose: reading back");
  buffers.put(std::move(out));
}

}  // namespace voxgi::gpu
