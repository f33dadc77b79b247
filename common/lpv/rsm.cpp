#include "common/lpv/rsm.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/camera_geometry.h"
#include "common/lights.h"

namespace voxgi::lpv {
namespace {

using glm::dvec3;

// A spot wider than this (full angle) gets the six faces of a point light: one frustum's texels
// would grow without bound toward 180 degrees.
constexpr double kSingleViewSpotDeg = 120.0;
// How far an emissive triangle's views start in front of it, in cells: five times the GPU's near
// plane (rsmViewProjection).
constexpr double kTriangleViewLift = 0.05;

// Whether light i of `lights` (sceneLights: the scene's analytic lights, then its emissive
// triangles) gets six cube faces.
bool cubeMapped(const Scene& scene, const std::vector<shared::LightData>& lights, size_t i) {
  if (lights[i].kind == shared::kLightTriangle) return true;
  const Light& l = scene.lights[i];
  return l.type == Light::Type::point ||
         (l.type == Light::Type::spot && l.spotAngleDeg > kSingleViewSpotDeg);
}

// A triangle light's corners (shaders/shared/lighting.h keeps them in position, direction and
// falloff), voxel-local.
std::array<dvec3, 3> triangleCorners(const shared::LightData& l) {
  return {dvec3(glm::vec3(l.position)), dvec3(glm::vec3(l.direction)), dvec3(glm::vec3(l.falloff))};
}

shared::RsmView view(dvec3 origin, bool perspective, dvec3 forward, double extent, int light,
                     int first, int count) {
  forward = glm::normalize(forward);
  const dvec3 hint = std::abs(forward.y) > 0.9 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
  const dvec3 right = glm::normalize(glm::cross(forward, hint));
  const dvec3 up = glm::cross(right, forward);
  shared::RsmView v{};
  v.origin = glm::vec3(origin);
  v.perspective = perspective ? 1 : 0;
  v.forward = glm::vec3(forward);
  v.extent = static_cast<float>(extent);
  v.right = glm::vec3(right);
  v.up = glm::vec3(up);
  v.light = light;
  v.firstView = first;
  v.viewCount = count;
  return v;
}

// The grid's corners in world units.
std::vector<dvec3> gridCorners(const GridSpec& g) {
  std::vector<dvec3> out;
  for (int c = 0; c < 8; ++c)
    out.push_back(g.min + g.size * dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  return out;
}

// Sum over a perspective view's texels of the solid angle the midpoint rule gives them.
double viewSolidAngle(double tanHalf, int resolution) {
  const double a = 2.0 * tanHalf / resolution;
  double sum = 0.0;
  for (int j = 0; j < resolution; ++j)
    for (int i = 0; i < resolution; ++i) {
      const double x = (2.0 * (i + 0.5) / resolution - 1.0) * tanHalf;
      const double y = (2.0 * (j + 0.5) / resolution - 1.0) * tanHalf;
      sum += a * a / std::pow(1.0 + x * x + y * y, 1.5);
    }
  return sum;
}

}  // namespace

int rsmViewCount(const Scene& scene, const Settings& s) {
  const std::vector<shared::LightData> lights = sceneLights(scene, s.vct.emitters);
  int count = 0;
  for (size_t i = 0; i < lights.size(); ++i) count += cubeMapped(scene, lights, i) ? 6 : 1;
  return count;
}

RsmSetup prepareRsm(const Scene& scene, const Settings& s) {
  const GridSpec& grid = scene.grid;
  const double n = grid.resolution;
  RsmSetup out;
  out.lights = sceneLights(scene, s.vct.emitters);
  // The directional views start behind everything: the farthest vertex or corner from the centre.
  const dvec3 centre(0.5 * n);
  double reach = 0.5 * std::sqrt(3.0) * n;
  for (const Mesh& m : scene.meshes)
    for (const glm::dvec3& p : m.positions)
      reach = std::max(reach, glm::length(grid.toVoxel(p) - centre));
  for (size_t i = 0; i < out.lights.size(); ++i) {
    const shared::LightData& l = out.lights[i];
    const int light = static_cast<int>(i), first = static_cast<int>(out.views.size());
    dvec3 at(glm::vec3(l.position));
    if (l.kind == shared::kLightTriangle) {
      // The centroid, moved kTriangleViewLift cells off the emitting side: a view starting on the
      // triangle would meet it and its neighbours at depth 0, where the rasterizer's near plane
      // (1e-2 cells) and a ray cast disagree.
      const std::array<dvec3, 3> c = triangleCorners(l);
      at = (c[0] + c[1] + c[2]) / 3.0 +
           kTriangleViewLift * glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
    }
    if (cubeMapped(scene, out.lights, i)) {
      for (int f = 0; f < 6; ++f) {
        dvec3 axis(0.0);
        axis[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
        out.views.push_back(view(at, true, axis, 1.0, light, first, 6));
      }
    } else if (l.kind == shared::kLightSpot) {
      const double tanHalf = std::tan(0.5 * scene.lights[i].spotAngleDeg * M_PI / 180.0);
      out.views.push_back(view(at, true, scene.lights[i].direction, tanHalf, light, first, 1));
    } else {
      const dvec3 d = glm::normalize(scene.lights[i].direction);
      out.views.push_back(
          view(centre - d * (reach + 1.0), false, d, 0.5 * std::sqrt(3.0) * n, light, first, 1));
    }
  }
  out.params.resolution = s.lpv.rsmResolution;
  out.params.viewCount = int(out.views.size());
  out.params.lightCount = int(out.lights.size());
  out.params.voxelSize = static_cast<float>(grid.voxelSize());
  out.params.biasTexels = s.lpv.rsmBias;
  return out;
}

glm::mat4 rsmViewProjection(const shared::RsmView& v, float farPlane) {
  const glm::mat4 view =
      viewMatrix(glm::vec3(v.origin), glm::vec3(v.forward), glm::vec3(v.right), glm::vec3(v.up));
  const float extent = v.extent;
  if (v.perspective == 1) return flippedPerspective(extent, extent, 1e-2f, farPlane) * view;
  // Orthographic: depth [0, far] to [-1, 1], y flipped as the perspective one.
  glm::mat4 proj(0.0f);
  proj[0][0] = 1.0f / extent;
  proj[1][1] = -1.0f / extent;
  proj[2][2] = -2.0f / farPlane;
  proj[3][2] = -1.0f;
  proj[3][3] = 1.0f;
  return proj * view;
}

float rsmFarPlane(const Scene& scene, const RsmSetup& rsm) {
  double farthest = 1.0;
  for (const shared::RsmView& v : rsm.views)
    for (const Mesh& m : scene.meshes)
      for (const glm::dvec3& p : m.positions)
        farthest = std::max(farthest, glm::length(scene.grid.toVoxel(p) - dvec3(v.origin)));
  return static_cast<float>(2.0 * farthest);
}

glm::dvec3 rsmFluxBound(const Scene& scene, const RsmSetup& rsm) {
  const GridSpec& grid = scene.grid;
  dvec3 albedo(0.0);
  for (const Material& m : scene.materials) albedo = glm::max(albedo, dvec3(m.albedo));
  const int resolution = rsm.params.resolution;
  const double s = grid.voxelSize();
  dvec3 total(0.0);
  double tanHalf = -1.0, solidAngle = 0.0;  // the last perspective view's (cube faces share it)
  for (const shared::LightData& l : rsm.lights) {
    if (l.kind != shared::kLightTriangle) continue;
    const std::array<dvec3, 3> c = triangleCorners(l);
    const double area = 0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0])) * s * s;
    total += M_PI * dvec3(glm::vec3(l.intensity)) * area;
  }
  for (const shared::RsmView& v : rsm.views) {
    if (rsm.lights[size_t(v.light)].kind == shared::kLightTriangle) continue;
    const Light& l = scene.lights[size_t(v.light)];
    if (v.perspective == 0) {  // the box's whole cross-section at the light's irradiance
      const double side = 2.0 * double(v.extent) * s;
      total += dvec3(l.intensity) * side * side;
      continue;
    }
    // r^2 x falloff(r) grows with r for non-negative coefficients: take the farthest corner.
    double r = 0.0;
    for (const dvec3& c : gridCorners(grid)) r = std::max(r, glm::length(c - l.position));
    const Falloff& f = l.falloff;
    const double spread =
        f.kind == Falloff::Kind::inverse_square
            ? 1.0
            : r * r / (double(f.constant) + double(f.linear) * r + double(f.quadratic) * r * r);
    if (double(v.extent) != tanHalf) {
      tanHalf = v.extent;
      solidAngle = viewSolidAngle(tanHalf, resolution);
    }
    total += dvec3(l.intensity) * spread * solidAngle;
  }
  return albedo * total;
}

}  // namespace voxgi::lpv
