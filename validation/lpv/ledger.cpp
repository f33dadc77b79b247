#include "validation/lpv/ledger.h"

#include <algorithm>
#include <cmath>

#include "common/lpv/inject.h"
#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "common/parallel.h"
#include "shaders/shared/lpv/propagate_kernel.h"
#include "shaders/shared/lpv/shade_kernel.h"

namespace voxgi::validation {
namespace {

// The flux of a lobe with coefficient c_0: c_0 times the integral of Y_0 over the sphere.
constexpr double kFluxPerC0 = 3.5449077018110318;  // 2 sqrt(pi)

bool inside(glm::ivec3 v, int n) {
  return glm::all(glm::greaterThanEqual(v, glm::ivec3(0))) &&
         glm::all(glm::lessThan(v, glm::ivec3(n)));
}

// One volume of 3C words per cell, and the geometry volume, as the shared kernels read them.
struct Volumes {
  const float* words;      // a volume of the series, or the accumulated one
  const Buffer* blocking;  // null without occlusion
  int n, coefficients;
  size_t index(glm::ivec3 v) const {
    return size_t(v.x) + size_t(n) * (size_t(v.y) + size_t(n) * size_t(v.z));
  }
  glm::vec4 blockingAt(glm::ivec3 g) const {
    if (blocking == nullptr || !inside(g, n)) return glm::vec4(0.0f);
    const size_t e = index(g);
    return {blocking->get<float>(e, 0), blocking->get<float>(e, 1), blocking->get<float>(e, 2),
            blocking->get<float>(e, 3)};
  }
  float accumulatedAt(glm::ivec3 cell, int word) const {
    if (!inside(cell, n)) return 0.0f;
    return words[index(cell) * size_t(3 * coefficients) + size_t(word)];
  }
};

// The flux of a volume: 2 sqrt(pi) sum c_0, per colour.
glm::dvec3 volumeFlux(const float* words, int n, int coefficients) {
  glm::dvec3 sum(0.0);
  const size_t cells = size_t(n) * size_t(n) * size_t(n), stride = size_t(3 * coefficients);
  for (size_t e = 0; e < cells; ++e)
    for (int c = 0; c < 3; ++c) sum[c] += double(words[e * stride + size_t(c * coefficients)]);
  return sum * kFluxPerC0;
}

// What step `step` does to LPV_{k-1}: every face entry of every source cell, as propagateCell
// computes it for the destination.
LedgerStep stepFlux(const Volumes& previous, const lpv::Propagation& setup, bool occlude,
                    bool clampNegative) {
  const int n = previous.n, coefficients = previous.coefficients;
  // One partial sum per slice of sources, added in order: the ledger is deterministic too.
  std::vector<LedgerStep> slices(static_cast<size_t>(n));
  parallelFor(0, n, [&](int z) {
    LedgerStep& s = slices[size_t(z)];
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::ivec3 src(x, y, z);
        const float* c = previous.words + previous.index(src) * size_t(3 * coefficients);
        for (const shared::PropagationEntry& f : setup.entries) {
          const glm::ivec3 dst = src + glm::ivec3(f.offset);
          double visibility = 1.0;
          if (occlude && inside(dst, n)) {
            const glm::vec4 b = shared::blockingBetween(previous, dst, glm::ivec3(f.offset));
            const float blocked = b.x * f.blocking[0] + b.y * f.blocking[1] + b.z * f.blocking[2] +
                                  b.w * f.blocking[3];
            visibility = 1.0 - double(std::clamp(blocked, 0.0f, 1.0f));
          }
          for (int colour = 0; colour < 3; ++colour) {
            double intensity = 0.0;
            for (int i = 0; i < coefficients; ++i)
              intensity += double(c[colour * coefficients + i]) * double(f.sampled[i]);
            if (clampNegative) intensity = std::max(intensity, 0.0);
            const double sent = intensity * double(f.reprojected[0]) * kFluxPerC0;
            s.sent[colour] += sent;
            if (!inside(dst, n))
              s.left[colour] += sent;
            else
              s.removed[colour] += sent * (1.0 - visibility);
          }
        }
      }
  });
  LedgerStep out;
  for (const LedgerStep& s : slices) {
    out.sent += s.sent;
    out.removed += s.removed;
    out.left += s.left;
  }
  out.arrived = out.sent - out.removed - out.left;
  return out;
}

// A point of a surface, voxel-local, with its unit normal and the world area it stands for.
struct SurfaceSample {
  glm::vec3 position, normal;
  double area;
};

// Each triangle of each mesh as m^2 congruent sub-triangles of at most `spacing` cells a side,
// one sample at each centroid (as injection places emitter VPLs). Per mesh, its samples.
std::vector<std::vector<SurfaceSample>> surfaceSamples(const Scene& scene, double spacing) {
  const GridSpec& grid = scene.grid;
  std::vector<std::vector<SurfaceSample>> out;
  for (const Mesh& mesh : scene.meshes) {
    out.emplace_back();
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 a = grid.toVoxel(mesh.positions[t.x]), b = grid.toVoxel(mesh.positions[t.y]),
                       c = grid.toVoxel(mesh.positions[t.z]);
      const glm::dvec3 cross = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                          mesh.positions[t.z] - mesh.positions[t.x]);
      const double twiceArea = glm::length(cross);
      if (!(twiceArea > 0.0)) continue;
      const double edge = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
      const double m = std::min(std::max(1.0, std::ceil(edge / spacing)), 4096.0);
      const glm::vec3 normal(cross / twiceArea);
      const double area = 0.5 * twiceArea / (m * m);
      const auto add = [&](double u, double v) {
        out.back().push_back({glm::vec3(a + u * (b - a) + v * (c - a)), normal, area});
      };
      for (int i = 0; i < int(m); ++i)
        for (int j = 0; i + j < int(m); ++j) {
          add((i + 1.0 / 3.0) / m, (j + 1.0 / 3.0) / m);
          if (i + j + 1 < int(m)) add((i + 2.0 / 3.0) / m, (j + 2.0 / 3.0) / m);
        }
    }
  }
  return out;
}

// The irradiance shading reads from `volume`, integrated over `samples`.
glm::dvec3 readFlux(const Volumes& volume, const std::vector<SurfaceSample>& samples,
                    const shared::ShadeParams& params) {
  const size_t chunk = 4096, chunks = (samples.size() + chunk - 1) / chunk;
  std::vector<glm::dvec3> partial(chunks, glm::dvec3(0.0));
  parallelFor(0, int(chunks), [&](int k) {
    const size_t end = std::min(samples.size(), (size_t(k) + 1) * chunk);
    for (size_t i = size_t(k) * chunk; i < end; ++i) {
      const SurfaceSample& s = samples[i];
      const glm::vec3 e = shared::lpvIrradiance(volume, s.position, s.normal, params);
      partial[size_t(k)] += glm::dvec3(e) * (M_PI * s.area);
    }
  });
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : partial) sum += p;
  return sum;
}

}  // namespace

Ledger lpvLedger(const StageContext& ctx, const BufferSet& buffers, double spacing) {
  const LpvSettings& s = ctx.settings.lpv;
  const lpv::ShBuffers sh = lpv::shBuffers(s);
  const int n = ctx.scene.grid.resolution, coefficients = s.coefficients();
  const lpv::Propagation setup = lpv::preparePropagation(s, n);
  const Buffer& series = buffers.at(sh.steps);
  const auto* words = reinterpret_cast<const float*>(series.words.data());
  const size_t volumeWords = size_t(n) * size_t(n) * size_t(n) * size_t(3 * coefficients);
  const Buffer* blocking = buffers.find(BufferId::lpv_inject_geometry_blocking);
  const shared::ShadeParams shade = lpv::shadeParams(ctx);
  const std::vector<std::vector<SurfaceSample>> perMesh = surfaceSamples(ctx.scene, spacing);
  std::vector<SurfaceSample> every;
  for (const auto& m : perMesh) every.insert(every.end(), m.begin(), m.end());

  Ledger ledger;
  for (const Mesh& mesh : ctx.scene.meshes) {
    const Material& mat = ctx.scene.materials.at(mesh.material);
    if (!mat.emissive()) continue;
    for (const glm::uvec3& t : mesh.triangles)
      ledger.emitted += M_PI * glm::dvec3(mat.emission) * 0.5 *
                        glm::length(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                               mesh.positions[t.z] - mesh.positions[t.x]));
  }
  if (const Buffer* flux = buffers.find(BufferId::lpv_rsm_flux))
    for (size_t e = 0; e < flux->elementCount(); ++e) ledger.emitted += glm::dvec3(flux->vec3At(e));
  ledger.injected = volumeFlux(words, n, coefficients);
  ledger.readInjected = readFlux({words, blocking, n, coefficients}, every, shade);
  for (int k = 1; k <= setup.steps; ++k) {
    const Volumes previous{words + size_t(k - 1) * volumeWords, blocking, n, coefficients};
    LedgerStep step = stepFlux(previous, setup, lpv::occludedStep(s, k) && blocking != nullptr,
                               s.clampNegative == LpvToggle::on);
    step.step = k;
    const float* current = words + size_t(k) * volumeWords;
    step.volume = volumeFlux(current, n, coefficients);
    step.read = readFlux({current, blocking, n, coefficients}, every, shade);
    ledger.steps.push_back(step);
  }
  const auto* accumulated = reinterpret_cast<const float*>(buffers.at(sh.accumulated).words.data());
  for (size_t m = 0; m < perMesh.size(); ++m) {
    LedgerSurface surface{ctx.scene.meshes[m].name, 0.0,
                          readFlux({accumulated, blocking, n, coefficients}, perMesh[m], shade)};
    for (const SurfaceSample& p : perMesh[m]) surface.area += p.area;
    ledger.read += surface.read;
    ledger.surfaces.push_back(surface);
  }
  const double cell = ctx.scene.grid.voxelSize();
  double area = 0.0;
  for (const LedgerSurface& surface : ledger.surfaces) area += surface.area;
  ledger.samplesPerCell = area > 0.0 ? double(every.size()) * cell * cell / area : 0.0;
  return ledger;
}

}  // namespace voxgi::validation
