#include "cpu/svo/shade.h"

#include "shaders/shared/compose_kernel.h"
#include "shaders/shared/svo/shade_kernel.h"
#include "shaders/shared/vct/trace_cones_kernel.h"

namespace voxgi::cpu::svo {

PixelShading shadePixels(const BufferSet& gbuffer, const Octree& octree, const Leaves& leaves,
                         const LeafRadiance& radiance, const NodeLevels& mips,
                         const Words& gatheredBricks, const std::vector<shared::LightData>& lights,
                         const std::vector<shared::ObjectData>& objects,
                         const shared::ConeTraceParams& params, glm::vec3 background,
                         bool tricubic) {
  const Buffer& position = gbuffer.at(BufferId::common_gbuffer_pixel_position);
  const Buffer& normal = gbuffer.at(BufferId::common_gbuffer_pixel_normal);
  const Buffer& albedo = gbuffer.at(BufferId::common_gbuffer_pixel_albedo);
  const Buffer& specular = gbuffer.at(BufferId::common_gbuffer_pixel_specular);
  const Buffer* emission = gbuffer.find(BufferId::common_gbuffer_pixel_emission);
  const Buffer& object = gbuffer.at(BufferId::common_gbuffer_object_id);
  const size_t pixels = position.elementCount();
  PixelShading out;
  out.light.resize(pixels);
  out.color.resize(pixels);
  parallelFor(size_t(0), pixels, [&](size_t i) {
    const uint32_t id = object.get<uint32_t>(i, 0);
    if (id == 0u) {
      out.light[i] = {};
      out.color[i] = background;
      return;
    }
    SvoVolumes volumes{octree, leaves, &radiance, &mips, nullptr, &lights, nullptr};
    volumes.leafBricks = &gatheredBricks;
    const glm::vec3 p = position.vec3At(i);
    shared::PixelLight l = shared::tracePixel(volumes, p, normal.vec3At(i), objects[id], params);
    l.indirectDiffuse = tricubic ? shared::svoIrradianceTricubic(volumes, p, octree.depth)
                                 : shared::svoIrradiance(volumes, p, octree.depth);
    out.light[i] = l;
    const glm::vec4 s(specular.vec3At(i), 0.0f);
    out.color[i] = shared::composePixel(
        id, albedo.vec3At(i), glm::vec3(s), emission ? emission->vec3At(i) : glm::vec3(0.0f),
        l.directDiffuse, l.directSpecular, l.indirectDiffuse, l.indirectSpecular, 0.0f, background);
  });
  return out;
}

}  // namespace voxgi::cpu::svo
