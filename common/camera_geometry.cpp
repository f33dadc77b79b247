#include "common/camera_geometry.h"

#include <cmath>

#include "common/texture.h"
#include "shaders/shared/camera.h"

namespace voxgi {

glm::vec3 CameraRays::pixelDirection(int x, int y) const {
  return shared::pixelDirection(forward, right, up, tanHalfFov, aspect,
                                {float(x) + 0.5f, float(y) + 0.5f}, {float(width), float(height)});
}

glm::mat4 viewMatrix(glm::vec3 origin, glm::vec3 forward, glm::vec3 right, glm::vec3 up) {
  // Rows of the view matrix are the eye's axes.
  glm::mat4 view(1.0f);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = right[i];
    view[i][1] = up[i];
    view[i][2] = -forward[i];
  }
  view[3] =
      glm::vec4(-glm::dot(right, origin), -glm::dot(up, origin), glm::dot(forward, origin), 1.0f);
  return view;
}

glm::mat4 flippedPerspective(float tanX, float tanY, float nearPlane, float farPlane) {
  glm::mat4 proj(0.0f);
  proj[0][0] = 1.0f / tanX;
  proj[1][1] = -1.0f / tanY;  // flipped: GL row 0 is the image's top row
  proj[2][2] = -(farPlane + nearPlane) / (farPlane - nearPlane);
  proj[2][3] = -1.0f;
  proj[3][2] = -2.0f * farPlane * nearPlane / (farPlane - nearPlane);
  return proj;
}

glm::mat4 CameraRays::viewProjection(float nearPlane, float farPlane) const {
  return flippedPerspective(tanHalfFov * aspect, tanHalfFov, nearPlane, farPlane) *
         viewMatrix(origin, forward, right, up);
}

CameraRays cameraRays(const Scene& scene) {
  CameraRays r;
  const Camera& cam = scene.camera;
  const glm::dvec3 forward = glm::normalize(cam.lookAt - cam.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, cam.up));
  r.origin = glm::vec3(scene.grid.toVoxel(cam.position));
  r.forward = glm::vec3(forward);
  r.right = glm::vec3(right);
  r.up = glm::vec3(glm::cross(right, forward));
  r.tanHalfFov = static_cast<float>(std::tan(cam.fovYDeg * 3.14159265358979323846 / 360.0));
  r.width = cam.width;
  r.height = cam.height;
  r.aspect = float(cam.width) / float(cam.height);
  return r;
}

std::vector<shared::MaterialData> materialData(const Scene& scene) {
  std::vector<shared::MaterialData> out;
  for (const Material& m : scene.materials)
    out.push_back({glm::vec4(m.albedo, 0.0f), glm::vec4(m.specular, m.shininess),
                   glm::vec4(m.emission, 0.0f),
                   glm::uvec4(m.albedoTexture, m.emissionTexture, 0u, 0u)});
  return out;
}

CameraGeometry prepareCameraGeometry(const Scene& scene) {
  CameraGeometry g;
  const GridSpec& grid = scene.grid;
  g.camera = cameraRays(scene);
  double farthest = 1.0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double len = glm::length(n);
      SurfaceTriangle s{};
      s.normal = glm::vec4(len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f), 0.0f);
      s.objectId = uint32_t(m) + 1u;
      s.material = mesh.material;
      const glm::vec2 uv[3] = {mesh.texcoord(t.x), mesh.texcoord(t.y), mesh.texcoord(t.z)};
      s.uv0 = uv[0];
      s.uv1 = uv[1];
      s.uv2 = uv[2];
      s.uvPerVoxel = uvPerLength(uv, 0.5 * len / (grid.voxelSize() * grid.voxelSize()));
      g.triangles.push_back(s);
      for (const glm::dvec3& p : {a, b, c}) {
        const glm::dvec3 v = grid.toVoxel(p);
        g.vertices.emplace_back(v);
        farthest = std::max(farthest, glm::length(v - glm::dvec3(g.camera.origin)));
      }
    }
  }
  const double scale = 1.0 / grid.voxelSize();
  for (size_t c = 0; c < scene.pointClouds.size(); ++c) {
    const PointCloud& cloud = scene.pointClouds[c];
    const glm::vec3 albedo = scene.materials.at(cloud.material).albedo;
    const uint32_t object = uint32_t(scene.meshes.size() + c) + 1u;
    for (size_t i = 0; i < cloud.size(); ++i) {
      const glm::dvec3 v = grid.toVoxel(cloud.positions[i]);
      const double r = double(cloud.radii[i]) * scale;
      SurfaceDisc d{};
      d.center = glm::vec3(v);
      d.radius = float(r);
      d.normal = cloud.normals[i];
      d.albedo = cloud.colors.empty() ? albedo : cloud.colors[i];
      d.objectId = object;
      d.material = cloud.material;
      g.discs.push_back(d);
      farthest = std::max(farthest, glm::length(v - glm::dvec3(g.camera.origin)) + r);
    }
  }
  g.farPlane = static_cast<float>(2.0 * farthest);
  return g;
}

}  // namespace voxgi
