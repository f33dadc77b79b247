// GPU shade stage: shaders/svo/shade.comp lights the gbuffer's pixels from the tree, its cones
// reading every level as bricks (gpu/svo/bricks.h, completeBricks); the light terms and the
// colour are read back.
#include <bit>

#include "common/gbuffer.h"
#include "common/svo/stage_inputs.h"
#include "common/svo/tree_depth.h"
#include "gpu/program.h"
#include "gpu/stages.h"
#include "gpu/svo/bricks.h"
#include "gpu/volumes.h"
#include "shaders/shared/svo/svo_layout.h"
#include "shaders/shared/cone/mip.h"

namespace voxgi::gpu {

void svo::shade(GlContext& context, const StageContext& ctx, BufferSet& buffers) {
  using namespace voxgi::svo;
  const Gl& gl = beginStage(context, ctx, StageId::svo_shade);
  const int depth = treeDepth(ctx.scene);
  const ConeTraceSetup trace = treeConeTrace(ctx, depth);
  const GbufferView gbuffer(buffers);
  const Buffer &position = gbuffer.position, &normal = gbuffer.normal, &albedo = gbuffer.albedo,
               &specular = gbuffer.specular, *emission = gbuffer.emission,
               &object = gbuffer.objectId;
  const glm::ivec3 extent = position.extent;
  const size_t pixels = position.elementCount();
  // shade.comp's five vec4 a pixel.
  std::vector<glm::vec4> packed(5 * pixels);
  for (size_t e = 0; e < pixels; ++e) {
    packed[5 * e] = glm::vec4(position.vec3At(e), std::bit_cast<float>(object.get<uint32_t>(e, 0)));
    packed[5 * e + 1] = glm::vec4(normal.vec3At(e), 0.0f);
    packed[5 * e + 2] = glm::vec4(albedo.vec3At(e), 0.0f);
    packed[5 * e + 3] = glm::vec4(specular.vec3At(e), 0.0f);
    packed[5 * e + 4] = glm::vec4(emission ? emission->vec3At(e) : glm::vec3(0.0f), 0.0f);
  }
  const Buffer& nodeWords = buffers.at(BufferId::svo_build_nodes);
  GlBuffer nodes(gl, uploadWords(gl, nodeWords));
  // The light as the buffers hold it, in halves (shaders/svo/svo_pyramid.glsl).
  GlBuffer source(gl, uploadWords(gl, buffers.at(BufferId::svo_propagate_radiance)));
  GlBuffer faces(gl, uploadWords(gl, buffers.at(BufferId::svo_mip_node_faces)));
  GlBuffer bricks(gl, uploadWords(gl, buffers.at(BufferId::svo_propagate_gathered_bricks)));
  // The cones read the radiance and the node faces as bricks, as the gather does.
  const Buffer& leafTileWords = buffers.at(BufferId::svo_build_leaf_tiles);
  const Buffer& tileWords = buffers.at(BufferId::svo_build_tiles);
  GlBuffer leafTiles(gl, uploadWords(gl, leafTileWords));
  GlBuffer tiles(gl, uploadWords(gl, tileWords));
  GlBuffer leafBricks(gl, svo::completeBricks(gl, nodes.get(), leafTiles.get(), source.get(),
                                              leafTileWords.words.size() / shared::kTileWords, 1));
  GlBuffer nodeBricks(
      gl, svo::completeBricks(gl, nodes.get(), tiles.get(), faces.get(),
                              tileWords.words.size() / shared::kTileWords, shared::kFaces));
  GlBuffer lights(gl, createBlock(gl, trace.params, trace.lights));
  GlBuffer objects(
      gl, createBuffer(gl, trace.objects.size() * sizeof(trace.objects[0]), trace.objects.data()));
  GlBuffer pixelBlock(gl, createBuffer(gl, packed.size() * sizeof(glm::vec4), packed.data()));
  GlBuffer terms(gl, createBuffer(gl, packed.size() * sizeof(glm::vec4), nullptr));

  Program program(gl, {&shaders::svo_shade_comp});
  program.set("uDepth", depth);
  program.set("uWidth", extent.x);
  program.set("uHeight", extent.y);
  program.set("uBackground", ctx.scene.background);
  program.set("uTricubic", ctx.settings.svo.shadeFilter == SvoShadeFilter::tricubic ? 1 : 0);
  program.use();
  const GLuint blocks[] = {nodes.get(),  source.get(),  faces.get(),      bricks.get(),
                           lights.get(), objects.get(), pixelBlock.get(), terms.get()};
  for (GLuint i = 0; i < 8; ++i) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, blocks[i]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, leafBricks.get());
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, nodeBricks.get());
  gl.DispatchCompute(GLuint((extent.x + 7) / 8), GLuint((extent.y + 7) / 8), 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.check("shade: dispatch");
  std::vector<glm::vec4> values(packed.size());
  gl.GetNamedBufferSubData(terms.get(), 0, GLsizeiptr(values.size() * sizeof(glm::vec4)),
                           values.data());
  gl.check("shade: reading back");
  const BufferId ids[] = {BufferId::svo_shade_direct_diffuse, BufferId::svo_shade_direct_specular,
                          BufferId::svo_shade_indirect_diffuse,
                          BufferId::svo_shade_indirect_specular, BufferId::svo_shade_color};
  for (size_t k = 0; k < std::size(ids); ++k) {
    if (!bufferNeeded(bufferSpec(ids[k]), ctx.plan)) continue;
    Buffer out(ids[k], extent);
    for (size_t e = 0; e < pixels; ++e) out.setVec3(e, glm::vec3(values[5 * e + k]));
    buffers.put(std::move(out));
  }
}

}  // namespace voxgi::gpu
