#include "common/scene_io/ray_scene.h"

#include <algorithm>
#include <vector>
#include <cmath>

#include <embree3/rtcore.h>

namespace voxgi {

struct RayScene::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

RayScene::RayScene(BuildQuality quality) : handles_(new Handles) {
  handles_->device = rtcNewDevice("threads=0");
  handles_->scene = rtcNewScene(handles_->device);
  if (quality == BuildQuality::high)
    rtcSetSceneBuildQuality(handles_->scene, RTC_BUILD_QUALITY_HIGH);
}

RayScene::~RayScene() {
  rtcReleaseScene(handles_->scene);
  rtcReleaseDevice(handles_->device);
  delete handles_;
}

void RayScene::addMesh(unsigned id, std::span<const glm::vec3> vertices,
                       std::span<const glm::uvec3> triangles) {
  RTCGeometry g = rtcNewGeometry(handles_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // At least one vertex, so that an empty mesh still has a valid buffer.
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        std::max<size_t>(1, vertices.size())));
  for (size_t i = 0; i < vertices.size(); ++i)
    for (int c = 0; c < 3; ++c) v[3 * i + size_t(c)] = vertices[i][c];
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) idx[3 * t + size_t(c)] = triangles[t][c];
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(handles_->scene, g, id);
  rtcReleaseGeometry(g);
}

void RayScene::addDiscs(unsigned id, std::span<const glm::vec3> centres,
                        std::span<const glm::vec3> normals, std::span<const float> radii) {
  RTCGeometry g = rtcNewGeometry(handles_->device, RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), centres.size()));
  auto* n = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), centres.size()));
  for (size_t i = 0; i < centres.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      v[4 * i + size_t(c)] = centres[i][c];
      n[3 * i + size_t(c)] = normals[i][c];
    }
    v[4 * i + 3] = radii[i];
  }
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(handles_->scene, g, id);
  rtcReleaseGeometry(g);
}

void RayScene::addTriangleSoup(unsigned id, std::span<const glm::vec3> vertices) {
  std::vector<glm::uvec3> triangles(vertices.size() / 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    triangles[t] = glm::uvec3(3 * t, 3 * t + 1, 3 * t + 2);
  addMesh(id, vertices, triangles);
}

void RayScene::commit() {
  rtcCommitScene(handles_->scene);
}

RayScene::Hit RayScene::intersect(glm::vec3 o, glm::vec3 d) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = INFINITY;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->scene, &context, &rh);
  Hit h;
  h.found = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  h.t = rh.ray.tfar;
  h.geometry = rh.hit.geomID;
  h.primitive = rh.hit.primID;
  h.barycentric = {rh.hit.u, rh.hit.v};
  return h;
}

bool RayScene::occluded(glm::vec3 o, glm::vec3 d, float distance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r{};
  r.org_x = o.x, r.org_y = o.y, r.org_z = o.z;
  r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
  r.tnear = 0.0f;
  r.tfar = distance;
  r.mask = 0xFFFFFFFFu;
  rtcOccluded1(handles_->scene, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace voxgi
