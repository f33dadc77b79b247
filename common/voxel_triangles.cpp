#include "common/voxel_triangles.h"

#include <algorithm>
#include <cmath>

#include "common/parallel.h"
#include "common/texture.h"
#include "shaders/shared/voxelize_kernel.h"

namespace voxgi {
namespace {

using Polygon = std::vector<glm::dvec3>;

// Sutherland-Hodgman against the box [lo, hi]^3, in double.
Polygon clipToBox(Polygon poly, double lo, double hi) {
  for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
    const int axis = plane / 2;
    const double side = plane % 2 == 0 ? -1.0 : 1.0;
    const double bound = plane % 2 == 0 ? lo : hi;
    Polygon next;
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec3& p = poly[i];
      const glm::dvec3& q = poly[(i + 1) % poly.size()];
      const double dp = side * (p[axis] - bound);
      const double dq = side * (q[axis] - bound);
      if (dp <= 0.0) next.push_back(p);
      if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
        glm::dvec3 x = p + (dp / (dp - dq)) * (q - p);
        x[axis] = bound;
        next.push_back(x);
      }
    }
    poly = std::move(next);
  }
  return poly;
}

using Counts = VoxelTriangleCounts;

// A point's texture coordinates on the triangle `p` with coordinates `uv` (its barycentric weights
// by least squares in double, so a clipped piece's corners keep the original's mapping).
glm::vec2 texcoordAt(const glm::dvec3& x, const glm::dvec3 p[3], const glm::vec2 uv[3]) {
  const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], r = x - p[0];
  const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
  const double det = a * c - b * b;
  if (!(det > 0.0)) return uv[0];
  const double b1 = (c * glm::dot(e1, r) - b * glm::dot(e2, r)) / det;
  const double b2 = (a * glm::dot(e2, r) - b * glm::dot(e1, r)) / det;
  return glm::vec2((1.0 - b1 - b2) * glm::dvec2(uv[0]) + b1 * glm::dvec2(uv[1]) +
                   b2 * glm::dvec2(uv[2]));
}

void emitTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::vec2 uv[3], const Material& material, float emissionScale,
                  std::vector<shared::VoxelTriangle>& out, Counts& counts) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double twiceArea = glm::length(n);
  if (!(twiceArea > 0.0)) {
    ++counts.degenerate;
    return;
  }
  const unsigned axis = dominantAxis(n);
  shared::VoxelTriangle t{};
  t.v0 = glm::vec3(a);
  t.v1 = glm::vec3(b);
  t.v2 = glm::vec3(c);
  // The kernels divide by the float normal's dominant component: it must not vanish.
  const glm::vec3 nf = shared::cross3(t.v1 - t.v0, t.v2 - t.v0);
  if (nf[static_cast<int>(axis)] == 0.0f) {
    ++counts.degenerate;
    return;
  }
  const double maxEdge = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  const auto subdivision = static_cast<unsigned>(std::max(1.0, std::ceil(2.0 * maxEdge)));
  const double area = 0.5 * twiceArea;
  t.albedo = material.albedo;
  t.areaScale = static_cast<float>(twiceArea / std::abs(n[int(axis)]));
  t.normal = glm::vec3(n / twiceArea);
  t.sampleArea = static_cast<float>(area / (double(subdivision) * subdivision));
  t.emission = emissionScale > 0.0f ? material.emission / emissionScale : glm::vec3(0.0f);
  t.dominantAxis = axis;
  t.subdivision = subdivision;
  t.albedoTexture = material.albedoTexture;
  t.emissionTexture = material.emissionTexture;
  t.uv0 = uv[0];
  t.uv1 = uv[1];
  t.uv2 = uv[2];
  // One voxel edge on the triangle: the footprint the voxel's texture mean is filtered over
  // (docs/textures.md).
  t.uvFootprint = uvPerLength(uv, area);
  out.push_back(t);
}

}  // namespace

unsigned dominantAxis(const glm::dvec3& n) {
  const glm::dvec3 a = glm::abs(n);
  if (a.x >= a.y && a.x >= a.z) return 0;
  return a.y >= a.z ? 1 : 2;
}

VoxelTriangles prepareVoxelTriangles(const Scene& scene, const GridSpec& grid,
                                     const VoxelTriangles& before,
                                     const std::vector<bool>& unchanged) {
  VoxelTriangles result;
  for (const Mesh& m : scene.meshes)
    if (!m.triangles.empty()) {
      const glm::vec3& e = scene.materials[m.material].emission;
      result.emissionScale = std::max({result.emissionScale, e.x, e.y, e.z});
    }
  // Work items: (mesh, first triangle) chunks, processed in parallel, concatenated in order.
  struct Chunk {
    size_t mesh, begin, end;
    std::vector<shared::VoxelTriangle> out;
    Counts counts;
  };
  std::vector<Chunk> chunks;
  const size_t chunkSize = 4096;
  // Reused triangles hold emission over the scale they were set up with.
  const bool reusable = before.emissionScale == result.emissionScale &&
                        before.meshFirst.size() == scene.meshes.size() + 1 &&
                        unchanged.size() == scene.meshes.size();
  const auto reused = [&](size_t mesh) { return reusable && unchanged[mesh]; };
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi)
    for (size_t b = 0; !reused(mi) && b < scene.meshes[mi].triangles.size(); b += chunkSize)
      chunks.push_back({mi, b, std::min(b + chunkSize, scene.meshes[mi].triangles.size()), {}, {}});
  const double lo = -1.0, hi = grid.resolution + 1.0;
  parallelFor(size_t(0), chunks.size(), [&](size_t ci) {
    Chunk& chunk = chunks[ci];
    const Mesh& mesh = scene.meshes[chunk.mesh];
    const Material& material = scene.materials[mesh.material];
    for (size_t ti = chunk.begin; ti < chunk.end; ++ti) {
      const glm::uvec3& tri = mesh.triangles[ti];
      const glm::dvec3 p[3] = {grid.toVoxel(mesh.positions[tri.x]),
                               grid.toVoxel(mesh.positions[tri.y]),
                               grid.toVoxel(mesh.positions[tri.z])};
      const glm::dvec3 bmin = glm::min(p[0], glm::min(p[1], p[2]));
      const glm::dvec3 bmax = glm::max(p[0], glm::max(p[1], p[2]));
      if (bmax.x < lo || bmax.y < lo || bmax.z < lo || bmin.x > hi || bmin.y > hi || bmin.z > hi) {
        ++chunk.counts.outside;
        continue;
      }
      const glm::vec2 uv[3] = {mesh.texcoord(tri.x), mesh.texcoord(tri.y), mesh.texcoord(tri.z)};
      if (bmin.x >= lo && bmin.y >= lo && bmin.z >= lo && bmax.x <= hi && bmax.y <= hi &&
          bmax.z <= hi) {
        emitTriangle(p[0], p[1], p[2], uv, material, result.emissionScale, chunk.out, chunk.counts);
        continue;
      }
      if (glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) == 0.0) {
        ++chunk.counts.degenerate;
        continue;
      }
      ++chunk.counts.clipped;
      const Polygon poly = clipToBox({p[0], p[1], p[2]}, lo, hi);
      for (size_t k = 1; k + 1 < poly.size(); ++k) {  // fan; zero-area pieces are dropped
        const glm::vec2 piece[3] = {texcoordAt(poly[0], p, uv), texcoordAt(poly[k], p, uv),
                                    texcoordAt(poly[k + 1], p, uv)};
        emitTriangle(poly[0], poly[k], poly[k + 1], piece, material, result.emissionScale,
                     chunk.out, chunk.counts);
      }
    }
  });
  // Each mesh in order: its triangles from `before`, or from its chunks.
  size_t chunk = 0;
  for (size_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
    Counts counts;
    if (reused(mesh)) {
      result.triangles.insert(result.triangles.end(),
                              before.triangles.begin() + ptrdiff_t(before.meshFirst[mesh]),
                              before.triangles.begin() + ptrdiff_t(before.meshFirst[mesh + 1]));
      counts = before.meshCounts[mesh];
    }
    for (; chunk < chunks.size() && chunks[chunk].mesh == mesh; ++chunk) {
      const Chunk& c = chunks[chunk];
      result.triangles.insert(result.triangles.end(), c.out.begin(), c.out.end());
      counts.degenerate += c.counts.degenerate;
      counts.outside += c.counts.outside;
      counts.clipped += c.counts.clipped;
    }
    result.meshFirst.push_back(result.triangles.size());
    result.meshCounts.push_back(counts);
    result.degenerate += counts.degenerate;
    result.outside += counts.outside;
    result.clipped += counts.clipped;
  }
  return result;
}

VoxelTriangles prepareVoxelTriangles(const Scene& scene, const GridSpec& grid) {
  return prepareVoxelTriangles(scene, grid, VoxelTriangles{}, {});
}

}  // namespace voxgi
