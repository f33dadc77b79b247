#include "common/lpv/inject.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/lights.h"
#include "common/lpv/rsm.h"
#include "common/memory.h"
#include "shaders/shared/lpv/inject_kernel.h"

namespace voxgi::lpv {
namespace {

using glm::dvec3;

// The largest power of two s with s x total <= 2^30 (1 for no light).
float fixedPointScale(double total) {
  if (!(total > 0.0)) return 1.0f;
  const int e = static_cast<int>(std::floor(std::log2(std::ldexp(1.0, 30) / total)));
  return static_cast<float>(std::ldexp(1.0, std::clamp(e, -120, 120)));
}

// An emissive triangle in voxel-local coordinates, and its subdivision.
struct Emitter {
  dvec3 a, b, c, normal, flux;  // flux: of the whole triangle, pi x emission x area
  uint64_t m;
};

struct Emitters {
  std::vector<Emitter> triangles;
  uint64_t vpls = 0;
  glm::vec4 scale{1.0f};
};

// The emissive triangles, and the scale from their flux plus the bound of the RSM texels' flux.
Emitters emitters(const StageContext& ctx) {
  const Scene& scene = ctx.scene;
  const GridSpec& grid = scene.grid;
  const double spacing = ctx.settings.lpv.emitterSpacing;  // in cells
  Emitters out;
  dvec3 total(0.0);
  // Under emitters.mode=area_lights the emitters light the volume through their RSM texels.
  const bool vpls = emittersFor(scene, ctx.settings.vct.emitters) == EmitterLighting::voxels;
  for (const Mesh& mesh : scene.meshes) {
    const Material& mat = scene.materials.at(mesh.material);
    if (!mat.emissive() || !vpls) continue;
    for (const glm::uvec3& t : mesh.triangles) {
      const dvec3 a = grid.toVoxel(mesh.positions[t.x]), b = grid.toVoxel(mesh.positions[t.y]),
                  c = grid.toVoxel(mesh.positions[t.z]);
      const dvec3 cross = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                     mesh.positions[t.z] - mesh.positions[t.x]);
      const double twiceArea = glm::length(cross);  // world units
      if (!(twiceArea > 0.0)) continue;
      const double edge =
          std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});  // cells
      const double m = std::min(std::max(1.0, std::ceil(edge / spacing)), 1e6);
      out.vpls = m >= 1e6 ? UINT64_MAX : out.vpls + uint64_t(m) * uint64_t(m);
      const dvec3 flux = M_PI * dvec3(mat.emission) * (0.5 * twiceArea);
      out.triangles.push_back({a, b, c, cross / twiceArea, flux, uint64_t(m)});
      total += flux;
    }
  }
  const RsmSetup rsm = prepareRsm(scene, ctx.settings);
  if (!rsm.views.empty()) total += rsmFluxBound(scene, rsm);
  out.scale =
      glm::vec4(fixedPointScale(total.x), fixedPointScale(total.y), fixedPointScale(total.z), 0.0f);
  return out;
}

}  // namespace

glm::vec4 injectionScale(const StageContext& ctx) {
  return emitters(ctx).scale;
}

std::vector<float> injectedVolume(const StageContext& ctx, const Buffer& sums) {
  const int n = ctx.scene.grid.resolution, words = 3 * ctx.settings.lpv.coefficients();
  std::vector<float> out(sums.words.size());
  decodeInjected(ctx, sums, [&](int row, int x, int word, float value) {
    out[(size_t(row) * size_t(n) + size_t(x)) * size_t(words) + size_t(word)] = value;
  });
  return out;
}

Injection prepareInjection(const StageContext& ctx) {
  const LpvSettings& s = ctx.settings.lpv;
  const Emitters found = emitters(ctx);
  const uint64_t count = found.vpls;
  const uint64_t bytes =
      count > (UINT64_MAX / sizeof(shared::Vpl)) ? UINT64_MAX : count * sizeof(shared::Vpl);
  requireMemory(bytes, "the " + std::to_string(count) + " emitter VPLs", ctx.scene.file,
                "inject.emitter_spacing");
  if (count > uint64_t(INT32_MAX))
    throw InputError(ctx.scene.file, "inject.emitter_spacing",
                     std::to_string(count) + " emitter VPLs are more than one dispatch holds");

  Injection out;
  out.vpls.reserve(count);
  for (const Emitter& e : found.triangles) {
    const double m = double(e.m);
    const glm::vec4 flux(glm::vec3(e.flux / (m * m)), 0.0f);
    const glm::vec4 normal(glm::vec3(e.normal), 0.0f);
    const dvec3 shift = s.vplShift == LpvToggle::on ? 0.5 * e.normal : dvec3(0.0);
    const auto add = [&](double u, double v) {  // barycentric coordinates of b and c
      const dvec3 p = e.a + u * (e.b - e.a) + v * (e.c - e.a) + shift;
      out.vpls.push_back({glm::vec4(glm::vec3(p), 0.0f), normal, flux});
    };
    for (uint64_t i = 0; i < e.m; ++i)
      for (uint64_t j = 0; i + j < e.m; ++j) {
        add((double(i) + 1.0 / 3.0) / m, (double(j) + 1.0 / 3.0) / m);  // upright sub-triangle
        if (i + j + 1 < e.m) add((double(i) + 2.0 / 3.0) / m, (double(j) + 2.0 / 3.0) / m);
      }
  }
  out.params.resolution = ctx.scene.grid.resolution;
  out.params.coefficients = s.coefficients();
  out.params.vplCount = int(out.vpls.size());
  out.params.shiftRsmVpls = s.vplShift == LpvToggle::on ? 1 : 0;
  out.params.scale = found.scale;
  return out;
}

}  // namespace voxgi::lpv
