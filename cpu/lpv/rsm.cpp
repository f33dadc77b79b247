// CPU rsm stage: one Embree ray through every texel centre of every view (as the gbuffer stage
// casts its pixel rays); the nearest hit's flux, facing normal, depth and triangle go to the maps.
// Rows of all views are independent tasks.
#include "common/camera_geometry.h"
#include "common/lpv/rsm.h"
#include "common/parallel.h"
#include "common/scene_io/ray_scene.h"
#include "cpu/stages.h"
#include "common/texture.h"
#include "shaders/shared/lpv/rsm_kernel.h"
#include "shaders/shared/surface_hit.h"

namespace voxgi::cpu {

void lpv::rsm(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::lpv_rsm);
  const voxgi::lpv::RsmSetup setup = voxgi::lpv::prepareRsm(ctx.scene, ctx.settings);
  const std::vector<shared::LightData>& lights = setup.lights;
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  RayScene rays;
  rays.addTriangleSoup(0, g.vertices);
  rays.commit();
  const int r = setup.params.resolution, views = setup.params.viewCount;
  const float voxelSize = setup.params.voxelSize;
  const TextureAccess textures{ctx.scene.textures};
  const std::vector<shared::MaterialData> materials = materialData(ctx.scene);
  const glm::ivec3 extent(r, r * views, 1);
  using enum BufferId;
  Buffer flux(lpv_rsm_flux, extent), normal(lpv_rsm_normal, extent), depth(lpv_rsm_depth, extent),
      primitive(lpv_rsm_primitive_id, extent);
  parallelFor(0, r * views, [&](int row) {
    const shared::RsmView& v = setup.views[size_t(row / r)];
    const shared::LightData& light = lights[size_t(v.light)];
    for (int x = 0; x < r; ++x) {
      glm::vec3 origin, dir;
      shared::rsmTexelRay(v, {x, row % r}, r, origin, dir);
      const RayScene::Hit hit = rays.intersect(origin, dir);
      if (!hit.found) continue;
      const SurfaceTriangle& s = g.triangles[hit.primitive];
      const glm::vec3* t = &g.vertices[3 * size_t(hit.primitive)];
      const glm::vec3 b = shared::rayTriangleHit(origin, dir, t[0], t[1], t[2]);
      const float footprint = shared::rsmFootprint(v, dir, b.z, r, voxelSize);
      const glm::vec3 p = shared::rsmHitPoint(origin, dir, b.z);
      const glm::vec3 albedo =
          shared::surfaceAlbedo(textures, s, materials[s.material], {b.x, b.y},
                                shared::surfaceFootprint(s, shared::rsmTexelSide(v, b.z, r)));
      const size_t e = size_t(row) * size_t(r) + size_t(x);
      flux.setVec3(e, shared::rsmFlux(light, p, albedo, footprint, voxelSize));
      normal.setVec3(e, shared::facingNormal(glm::vec3(s.normal), dir));
      depth.set(e, 0, hit.t);
      primitive.set<uint32_t>(e, 0, hit.primitive + 1u);
    }
  });
  buffers.put(std::move(flux));
  buffers.put(std::move(normal));
  buffers.put(std::move(depth));
  buffers.put(std::move(primitive));
}

}  // namespace voxgi::cpu
