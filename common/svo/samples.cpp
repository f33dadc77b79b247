#include "common/svo/samples.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include <tbb/blocked_range.h>

#include "common/counter_random.h"
#include "common/error.h"
#include "common/memory.h"
#include "common/parallel.h"
#include "common/lights.h"
#include "common/surface_sampling.h"

namespace voxgi::svo {
namespace {

// The smallest power of two at least v (1 for v <= 0).
float powerOfTwoAtLeast(double v) {
  return v > 0.0 ? float(std::ldexp(1.0, int(std::ceil(std::log2(v))))) : 1.0f;
}

// Appends a cloud's points in leaf units.
void appendCloud(const Scene& scene, const PointCloud& cloud, double leaf,
                 std::vector<shared::SvoSample>& out) {
  const Material& m = scene.materials[cloud.material];
  const size_t first = out.size();
  out.resize(first + cloud.size());
  const glm::dvec3 origin = scene.grid.min;
  parallelFor(tbb::blocked_range<size_t>(0, cloud.size(), 16384),
              [&](const tbb::blocked_range<size_t>& r) {
                for (size_t i = r.begin(); i != r.end(); ++i) {
                  const double edge = std::sqrt(std::numbers::pi / 2.0) * cloud.radii[i] / leaf;
                  const auto e = float(std::clamp(edge, 1e-6, 1.0));
                  shared::SvoSample& s = out[first + i];
                  s.position = glm::vec3((cloud.positions[i] - origin) / leaf);
                  s.edge = e;
                  const glm::vec3 albedo = cloud.colors.empty() ? m.albedo : cloud.colors[i];
                  s.albedo = albedo;
                  s.density = 1.0f / e;
                  s.normal = cloud.normals[i];
                  s.emission = m.emission;  // scaled below
                }
              });
}

}  // namespace

SampleSet prepareSamples(const Scene& scene, int depth, double meshDensity, uint64_t seed,
                         EmitterLighting emitters) {
  const double leaf = scene.grid.size / double(1 << depth);
  SampleSet set;
  // Points per material of the meshes, decided before anything is allocated.
  std::vector<std::pair<uint32_t, size_t>> meshCounts;
  for (uint32_t m = 0; m < scene.materials.size(); ++m) {
    const double area = sampledArea(scene, int(m)) / (leaf * leaf);
    if (area > 0.0)
      meshCounts.push_back({m, size_t(std::max(1.0, std::round(area * meshDensity)))});
  }
  set.cloudPoints = scene.pointCount();
  for (const auto& [m, n] : meshCounts) set.meshPoints += n;
  // The samples, and a sampled cloud's positions, normals, colours and radii while it is built.
  requireMemory(
      (set.cloudPoints + set.meshPoints) * sizeof(shared::SvoSample) + set.meshPoints * 52u,
      std::to_string(set.cloudPoints + set.meshPoints) + " svo samples", scene.file,
      "build.mesh_density");
  set.samples.reserve(set.cloudPoints + set.meshPoints);
  const bool meshEmission = emittersFor(scene, emitters) == EmitterLighting::voxels;
  for (const PointCloud& cloud : scene.pointClouds) appendCloud(scene, cloud, leaf, set.samples);
  for (const auto& [m, n] : meshCounts) {
    SurfaceSampling sampling;
    sampling.points = n;
    sampling.material = int(m);
    sampling.seed = mix64(seed ^ mix64(m));
    const size_t first = set.samples.size();
    appendCloud(scene, sampleSurfaces(scene, sampling), leaf, set.samples);
    if (!meshEmission)
      for (size_t i = first; i < set.samples.size(); ++i) set.samples[i].emission = glm::vec3(0.0f);
  }

  // Emission as a fraction of the largest emission a sample carries.
  float brightest = 0.0f;
  for (const shared::SvoSample& s : set.samples)
    brightest = std::max({brightest, s.emission.x, s.emission.y, s.emission.z});
  set.emissionScale = powerOfTwoAtLeast(brightest);
  for (shared::SvoSample& s : set.samples) s.emission = s.emission / set.emissionScale;

  // The weight scale: count the samples whose RoI reaches each block of 8^3 leaves; a leaf's sum
  // is at most its block's count times the largest contribution of one sample (r^2).
  const int coarse = std::max(0, depth - 3);
  const int side = 1 << coarse;
  const float blockLeaves = float(1 << (depth - coarse));
  std::vector<std::atomic<uint32_t>> counts(size_t(side) * size_t(side) * size_t(side));
  std::atomic<uint32_t> largest{0};  // bits of the largest r^2 (non-negative floats order as ints)
  parallelFor(
      tbb::blocked_range<size_t>(0, set.samples.size(), 16384),
      [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          const glm::vec3 p = set.samples[i].position;
          const float edge = set.samples[i].edge;
          const uint32_t r2 = std::bit_cast<uint32_t>(edge * edge);
          uint32_t seen = largest.load();
          while (r2 > seen && !largest.compare_exchange_weak(seen, r2)) {
          }
          glm::ivec3 lo, hi;
          for (int a = 0; a < 3; ++a) {
            const float half = 0.5f * edge;
            lo[a] = int(std::clamp(std::floor((p[a] - half) / blockLeaves), 0.0f, float(side - 1)));
            hi[a] = int(std::clamp(std::floor((p[a] + half) / blockLeaves), 0.0f, float(side - 1)));
          }
          for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
              for (int x = lo.x; x <= hi.x; ++x)
                counts[size_t(x) + size_t(side) * (size_t(y) + size_t(side) * size_t(z))].fetch_add(
                    1, std::memory_order_relaxed);
        }
      });
  uint32_t most = 0;
  for (const auto& c : counts) most = std::max(most, c.load());
  const double bound = double(most) * double(std::bit_cast<float>(largest.load()));
  const int exponent =
      bound > 0.0 ? std::min(24, int(std::floor(std::log2(2147483647.0 / bound)))) : 24;
  set.weightScale = float(std::ldexp(1.0, exponent));
  return set;
}

}  // namespace voxgi::svo
