// CPU gbuffer stage: one Embree ray through every pixel centre; the nearest hit's position,
// facing normal and material go to the pixel buffers. Rows are independent tasks.

#include "common/parallel.h"
#include "common/camera_geometry.h"
#include "common/ray_scene.h"
#include "cpu/stages.h"
#include "shaders/shared/gbuffer_kernel.h"

namespace voxgi::cpu {

void common::gbuffer(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::common_gbuffer);
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const CameraRays& cam = g.camera;
  // One geometry of the camera geometry's triangles: primitive = triangle index.
  RayScene rays;
  rays.addTriangleSoup(0, g.vertices);
  rays.commit();
  const glm::ivec3 extent(cam.width, cam.height, 1);
  const bool emissive = ctx.plan.on(Effect::emission);
  Buffer position(BufferId::common_gbuffer_pixel_position, extent);
  Buffer normal(BufferId::common_gbuffer_pixel_normal, extent);
  Buffer albedo(BufferId::common_gbuffer_pixel_albedo, extent);
  Buffer specular(BufferId::common_gbuffer_pixel_specular, extent);
  Buffer emission = emissive ? Buffer(BufferId::common_gbuffer_pixel_emission, extent) : Buffer();
  Buffer objectId(BufferId::common_gbuffer_object_id, extent);
  Buffer primitiveId(BufferId::common_gbuffer_primitive_id, extent);
  parallelFor(0, cam.height, [&](int y) {
    for (int x = 0; x < cam.width; ++x) {
      const glm::vec3 d = cam.pixelDirection(x, y);
      const RayScene::Hit hit = rays.intersect(cam.origin, d);
      if (!hit.found) continue;
      const SurfaceTriangle& s = g.triangles[hit.primitive];
      const Material& m = ctx.scene.materials[s.info.y];
      const size_t e = size_t(y) * size_t(cam.width) + size_t(x);
      const glm::vec3 p = cam.origin + d * hit.t;
      const glm::vec3 n = shared::facingNormal(glm::vec3(s.normal), d);
      for (int c = 0; c < 3; ++c) {
        position.set(e, c, p[c]);
        normal.set(e, c, n[c]);
        albedo.set(e, c, m.albedo[c]);
        specular.set(e, c, m.specular[c]);
        if (emissive) emission.set(e, c, m.emission[c]);
      }
      specular.set(e, 3, m.shininess);
      objectId.set<uint32_t>(e, 0, s.info.x);
      primitiveId.set<uint32_t>(e, 0, hit.primitive + 1u);
    }
  });
  buffers.put(std::move(position));
  buffers.put(std::move(normal));
  buffers.put(std::move(albedo));
  buffers.put(std::move(specular));
  if (emissive) buffers.put(std::move(emission));
  buffers.put(std::move(objectId));
  buffers.put(std::move(primitiveId));
}

}  // namespace voxgi::cpu
