#include "common/cone/cone_trace.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/camera_geometry.h"
#include "common/lights.h"
#include "common/mips.h"
#include "common/cone/cone_sets.h"

namespace voxgi {
namespace {

// docs/stages/vct/trace_cones.md: the specular cone holds half the Phong lobe's energy.
std::vector<shared::ObjectData> objectData(const Scene& scene, bool everyObject) {
  // Object ids: meshes from 1, then the point clouds (gbuffer's numbering).
  std::vector<uint32_t> materials;
  for (const Mesh& m : scene.meshes) materials.push_back(m.material);
  for (const PointCloud& c : scene.pointClouds) materials.push_back(c.material);
  std::vector<shared::ObjectData> out(materials.size() + 1, shared::ObjectData{});
  for (size_t o = 0; o < materials.size(); ++o) {
    const Material& mat = scene.materials.at(materials[o]);
    if (!mat.glossy() && !everyObject) continue;
    // P(cos alpha > c) = 1 - c^(n+1) for a Phong lobe cos^n: half the energy within c =
    // 2^(-1/(n+1)).
    const double c = std::pow(2.0, -1.0 / (double(mat.shininess) + 1.0));
    out[o + 1].specularTanHalfAperture = float(std::sqrt(1.0 - c * c) / c);
    out[o + 1].shininess = mat.shininess;
  }
  return out;
}

}  // namespace

shared::ConeTraceParams coneTraceParams(const StageContext& ctx, int lightCount, int coneCount,
                                        glm::vec3 cameraPosition) {
  const VctSettings& s = ctx.settings.vct;
  const int n = ctx.scene.grid.resolution;
  // Every cone leaves the grid within its diagonal; 2N leaves room for the start offset.
  const float maxDistance = 2.0f * float(n);
  // Cone diameters are at least one voxel, so steps are at least beta; the bound keeps the loop
  // count under llvmpipe's and any driver's limits at large N and small beta.
  constexpr int kMaxSteps = 60000;
  const float minStep = std::max(s.coneStep, maxDistance / float(kMaxSteps - 2));
  const int steps = std::min(kMaxSteps, int(std::ceil(maxDistance / minStep)) + 2);
  const double halfShadow = 0.5 * double(s.shadowAperture) * std::numbers::pi / 180.0;
  // docs/stages/vct/trace_cones.md, "Self-occlusion": a start fixed in voxels comes closer to the
  // surface as the grid gets finer, while the coarse samples that occlude stay as wide.
  const float offset = s.coneOffsetUnit == ConeOffsetUnit::grid64
                           ? s.coneOffset * std::max(1.0f, float(n) / 64.0f)
                           : s.coneOffset;
  shared::ConeTraceParams p{};
  p.resolution = n;
  p.topLevel = mipLevelCount(n);
  p.directional = s.mip == MipMode::anisotropic ? 1 : 0;
  p.diffuseConeCount = coneCount;
  p.lightCount = lightCount;
  p.firstHitDiffuse = s.diffuseCones == DiffuseCones::first_hit ? 1 : 0;
  p.kahlShadow = s.shadowFalloff == ShadowFalloff::kahl2019 ? 1 : 0;
  p.lightAngleSpecular = s.specularBrdf == SpecularBrdf::light_angle ? 1 : 0;
  p.ambientOcclusion = ctx.plan.on(Effect::ambient_occlusion) ? 1 : 0;
  p.maxSteps = steps;
  p.diffuseScale = s.diffuseScale;
  p.coneStep = s.coneStep;
  p.coneOffset = offset;
  p.minStep = minStep;
  p.maxDistance = maxDistance;
  p.tanHalfShadowAperture = float(std::tan(halfShadow));
  p.shadowStrength = s.shadowStrength;
  p.ambientLambda = s.ambientLambda;
  p.voxelSize = float(ctx.scene.grid.voxelSize());
  p.specularFalloff = s.specularFalloff;
  p.specularGrace = 0.008f * std::numbers::pi_v<float>;
  p.coneClearance = s.coneClearance;
  p.background = glm::vec4(ctx.scene.background, 0.0f);
  p.camera = glm::vec4(cameraPosition, 0.0f);
  return p;
}

ConeTraceSetup prepareConeTrace(const StageContext& ctx) {
  ConeTraceSetup s{sceneLights(ctx.scene, ctx.settings.vct.emitters),
                   coneData(diffuseCones(ctx.settings.vct.cones)),
                   objectData(ctx.scene, ctx.plan.full),
                   {}};
  s.params =
      coneTraceParams(ctx, int(s.lights.size()), int(s.cones.size()), cameraRays(ctx.scene).origin);
  return s;
}

ConeTraceSetup prepareGather(const StageContext& ctx) {
  ConeTraceSetup s{{}, coneData(diffuseCones(ctx.settings.vct.cones)), {}, {}};
  s.params = coneTraceParams(ctx, 0, int(s.cones.size()), glm::vec3(0.0f));
  s.params.ambientOcclusion = 0;  // a gather collects radiance; occlusion is a pixel's
  return s;
}

}  // namespace voxgi
