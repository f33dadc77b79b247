#include "common/surface_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <sstream>

#include <tbb/blocked_range.h>

#include "common/counter_random.h"
#include "common/error.h"
#include "common/parallel.h"
#include "common/texture.h"

namespace voxgi {
namespace {

struct Triangle {
  glm::dvec3 a, ab, ac;
  glm::vec3 normal;
  uint32_t material;
  glm::vec2 uv[3];
  float uvPerLength;  // uv units per world unit of length on it
};

}  // namespace

PointCloud sampleSurfaces(const Scene& scene, const SurfaceSampling& sampling) {
  std::vector<Triangle> triangles;
  std::vector<double> cdf;  // running sum of the areas
  double area = 0.0;
  for (const Mesh& m : scene.meshes) {
    if (sampling.material < 0 ? scene.materials[m.material].emissive()
                              : m.material != uint32_t(sampling.material))
      continue;
    for (const glm::uvec3& t : m.triangles) {
      const glm::dvec3 a = m.positions[t.x], ab = m.positions[t.y] - a, ac = m.positions[t.z] - a;
      const glm::dvec3 n = glm::cross(ab, ac);
      const double twice = glm::length(n);
      if (!(twice > 0.0)) continue;
      const glm::vec2 uv[3] = {m.texcoord(t.x), m.texcoord(t.y), m.texcoord(t.z)};
      triangles.push_back({a,
                           ab,
                           ac,
                           glm::vec3(n / twice),
                           m.material,
                           {uv[0], uv[1], uv[2]},
                           voxgi::uvPerLength(uv, 0.5 * twice)});
      area += 0.5 * twice;
      cdf.push_back(area);
    }
  }
  if (triangles.empty())
    throw InputError(scene.file, "meshes", "no triangle with area and without emission to sample");
  // Named copies: a lambda may not capture structured bindings (clang 14).
  const glm::dvec3 lo = scene.bounds().first, hi = scene.bounds().second;
  // Density w(p) in [min(1, ratio), max(1, ratio)]; a candidate is kept with probability w / max.
  const auto density = [&](const glm::dvec3& p) {
    if (sampling.gradientAxis < 0) return 1.0;
    const int a = sampling.gradientAxis;
    const double span = hi[a] - lo[a];
    const double f = span > 0.0 ? std::clamp((p[a] - lo[a]) / span, 0.0, 1.0) : 0.0;
    return 1.0 + f * (sampling.gradientRatio - 1.0);
  };
  const double wMax = std::max(1.0, sampling.gradientRatio);
  // The mean density over the surface, to turn a point's density into its share of the area.
  double weighted = 0.0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    weighted += (cdf[t] - (t ? cdf[t - 1] : 0.0)) * density(tri.a + (tri.ab + tri.ac) / 3.0);
  }
  const double meanDensity = weighted / area;

  // A point's colour: its material's albedo, times the texture at its coordinates filtered over
  // the side of the square of its share of the area (docs/textures.md).
  const TextureAccess textures{scene.textures};
  const auto pointColour = [&](const Triangle& tri, double b1, double b2, double side) {
    const Material& m = scene.materials[tri.material];
    const glm::vec2 uv = glm::vec2(glm::dvec2(tri.uv[0]) * (1.0 - b1 - b2) +
                                   glm::dvec2(tri.uv[1]) * b1 + glm::dvec2(tri.uv[2]) * b2);
    return shared::texturedValue(textures, m.albedo, m.albedoTexture, uv,
                                 float(side) * tri.uvPerLength);
  };

  PointCloud cloud;
  cloud.name = scene.file + " (sampled)";
  cloud.material = sampling.material >= 0 ? uint32_t(sampling.material) : 0u;
  const size_t n = sampling.points;
  cloud.positions.resize(n);
  cloud.normals.resize(n);
  cloud.colors.resize(n);
  cloud.radii.resize(n);
  parallelFor(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      CounterRandom rng{mix64(sampling.seed ^ mix64(i + 0x2545f4914f6cdd1dull))};
      for (;;) {  // rejection by density; at most wMax / min(w) tries on average
        const double u = rng.nextDouble() * area;
        const size_t t = size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin());
        const Triangle& tri = triangles[std::min(t, triangles.size() - 1)];
        const double s = std::sqrt(rng.nextDouble()), v = rng.nextDouble();
        glm::dvec3 p = tri.a + tri.ab * (s * (1.0 - v)) + tri.ac * (s * v);
        const double w = density(p);
        if (rng.nextDouble() * wMax >= w) continue;
        if (sampling.noise > 0.0) {  // Box-Muller
          const double g = std::sqrt(-2.0 * std::log(1.0 - rng.nextDouble())) *
                           std::cos(2.0 * std::numbers::pi * rng.nextDouble());
          p += glm::dvec3(tri.normal) * (g * sampling.noise);
        }
        const double share = area / double(n) * meanDensity / w;  // area per point here
        cloud.positions[i] = p;
        cloud.normals[i] = tri.normal;
        cloud.colors[i] = pointColour(tri, s * (1.0 - v), s * v, std::sqrt(share));
        cloud.radii[i] = float(std::sqrt(2.0 * share / std::numbers::pi));
        break;
      }
    }
  });
  return cloud;
}

double sampledArea(const Scene& scene, int material) {
  double area = 0.0;
  for (const Mesh& m : scene.meshes) {
    if (material < 0 ? scene.materials[m.material].emissive() : m.material != uint32_t(material))
      continue;
    for (const glm::uvec3& t : m.triangles)
      area += 0.5 * glm::length(glm::cross(m.positions[t.y] - m.positions[t.x],
                                           m.positions[t.z] - m.positions[t.x]));
  }
  return area;
}

}  // namespace voxgi
