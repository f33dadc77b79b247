// CPU gbuffer stage: one Embree ray through every pixel centre; the nearest hit's position,
// facing normal and material go to the pixel buffers. Rows are independent tasks.
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include "common/camera_geometry.h"
#include "cpu/stages.h"
#include "shaders/shared/gbuffer_kernel.h"

namespace voxgi::cpu {
namespace {

// An Embree scene of the camera geometry's triangles (geometry 0, primitive = triangle index).
class RayScene {
 public:
  explicit RayScene(const CameraGeometry& g) {
    device_ = rtcNewDevice("threads=0");
    scene_ = rtcNewScene(device_);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t count = g.triangles.size();
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          std::max<size_t>(1, g.vertices.size())));
    for (size_t i = 0; i < g.vertices.size(); ++i)
      for (int c = 0; c < 3; ++c) v[3 * i + size_t(c)] = g.vertices[i][c];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    for (size_t i = 0; i < 3 * count; ++i) idx[i] = static_cast<unsigned>(i);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
  }
  ~RayScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // The nearest triangle along o + t d (t > 0), or -1; `t` gets its distance parameter.
  long long intersect(glm::vec3 o, glm::vec3 d, float& t) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = o.x;
    rh.ray.org_y = o.y;
    rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x;
    rh.ray.dir_y = d.y;
    rh.ray.dir_z = d.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
    t = rh.ray.tfar;
    return rh.hit.primID;
  }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace

void gbuffer(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, "gbuffer");
  const CameraGeometry g = prepareCameraGeometry(ctx.scene);
  const CameraRays& cam = g.camera;
  const RayScene rays(g);
  const glm::ivec3 extent(cam.width, cam.height, 1);
  const bool emissive = ctx.plan.emission;
  Buffer position(bufferSpec("gbuffer", "pixel_position"), extent);
  Buffer normal(bufferSpec("gbuffer", "pixel_normal"), extent);
  Buffer albedo(bufferSpec("gbuffer", "pixel_albedo"), extent);
  Buffer specular(bufferSpec("gbuffer", "pixel_specular"), extent);
  Buffer emission = emissive ? Buffer(bufferSpec("gbuffer", "pixel_emission"), extent) : Buffer();
  Buffer objectId(bufferSpec("gbuffer", "object_id"), extent);
  Buffer primitiveId(bufferSpec("gbuffer", "primitive_id"), extent);
  tbb::parallel_for(0, cam.height, [&](int y) {
    for (int x = 0; x < cam.width; ++x) {
      const glm::vec3 d = cam.pixelDirection(x, y);
      float t = 0.0f;
      const long long tri = rays.intersect(cam.origin, d, t);
      if (tri < 0) continue;
      const SurfaceTriangle& s = g.triangles[size_t(tri)];
      const Material& m = ctx.scene.materials[s.info.y];
      const size_t e = size_t(y) * size_t(cam.width) + size_t(x);
      const glm::vec3 p = cam.origin + d * t;
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
      primitiveId.set<uint32_t>(e, 0, static_cast<uint32_t>(tri) + 1u);
    }
  });
  buffers["pixel_position"] = std::move(position);
  buffers["pixel_normal"] = std::move(normal);
  buffers["pixel_albedo"] = std::move(albedo);
  buffers["pixel_specular"] = std::move(specular);
  if (emissive) buffers["pixel_emission"] = std::move(emission);
  buffers["object_id"] = std::move(objectId);
  buffers["primitive_id"] = std::move(primitiveId);
}

}  // namespace voxgi::cpu
