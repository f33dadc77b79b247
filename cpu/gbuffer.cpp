// CPU gbuffer stage: one Embree ray through every pixel centre; the nearest hit's position,
// facing normal and material go to the pixel buffers. Point clouds are Embree's oriented discs,
// numbered after the triangles. Rows are independent tasks.
#include <vector>

#include "common/parallel.h"
#include "common/camera_geometry.h"
#include "common/scene_io/ray_scene.h"
#include "cpu/stages.h"
#include "common/texture.h"
#include "shaders/shared/surface_hit.h"

namespace voxgi::cpu {

void common::gbuffer(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::common_gbuffer);
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const CameraRays& cam = g.camera;
  // Geometry 0: the camera geometry's triangles (primitive = triangle index); 1: its discs.
  RayScene rays;
  rays.addTriangleSoup(0, g.vertices);
  if (!g.discs.empty()) {
    std::vector<glm::vec3> centres, normals;
    std::vector<float> radii;
    for (const SurfaceDisc& d : g.discs) {
      centres.emplace_back(d.center);
      normals.emplace_back(d.normal);
      radii.push_back(d.radius);
    }
    rays.addDiscs(1, centres, normals, radii);
  }
  rays.commit();
  const auto triangleCount = uint32_t(g.triangles.size());
  const glm::ivec3 extent(cam.width, cam.height, 1);
  const bool emissive = ctx.plan.on(Effect::emission);
  const TextureAccess textures{ctx.scene.textures};
  const std::vector<shared::MaterialData> materials = materialData(ctx.scene);
  const float pixelSide = cam.pixelSide();
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
      const bool disc = hit.geometry == 1;
      const uint32_t object =
          disc ? g.discs[hit.primitive].objectId : g.triangles[hit.primitive].objectId;
      const uint32_t material =
          disc ? g.discs[hit.primitive].material : g.triangles[hit.primitive].material;
      const glm::vec3 surfaceNormal =
          disc ? g.discs[hit.primitive].normal : glm::vec3(g.triangles[hit.primitive].normal);
      const Material& m = ctx.scene.materials[material];
      glm::vec3 a = disc ? g.discs[hit.primitive].albedo : m.albedo, emitted = m.emission;
      if (!disc) {
        const SurfaceTriangle& s = g.triangles[hit.primitive];
        const glm::vec3* v = &g.vertices[3 * size_t(hit.primitive)];
        const glm::vec3 b = shared::rayTriangleHit(cam.origin, d, v[0], v[1], v[2]);
        const float footprint = shared::surfaceFootprint(s, b.z * pixelSide);
        a = shared::surfaceAlbedo(textures, s, materials[material], {b.x, b.y}, footprint);
        emitted = shared::surfaceEmission(textures, s, materials[material], {b.x, b.y}, footprint);
      }
      const size_t e = size_t(y) * size_t(cam.width) + size_t(x);
      const glm::vec3 p = cam.origin + d * hit.t;
      const glm::vec3 n = shared::facingNormal(surfaceNormal, d);
      for (int c = 0; c < 3; ++c) {
        position.set(e, c, p[c]);
        normal.set(e, c, n[c]);
        albedo.set(e, c, a[c]);
        specular.set(e, c, m.specular[c]);
        if (emissive) emission.set(e, c, emitted[c]);
      }
      specular.set(e, 3, m.shininess);
      objectId.set<uint32_t>(e, 0, object);
      primitiveId.set<uint32_t>(e, 0, (disc ? triangleCount : 0u) + hit.primitive + 1u);
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
