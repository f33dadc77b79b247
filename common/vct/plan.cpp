// Voxel cone tracing's effect planner (docs/effect-plan.md).
#include <sstream>

#include "common/lights.h"
#include "common/technique.h"
#include "common/cone/cone_sets.h"

namespace voxgi::vct {
namespace {

// Names of the meshes whose material passes `test`, and whether one of them is in view.
struct MeshesWith {
  std::string names;
  bool inView = false;
};
template <class Test>
MeshesWith meshesWith(const Scene& scene, Test test) {
  MeshesWith r;
  for (const Mesh& m : scene.meshes) {
    const Material& mat = scene.materials.at(m.material);
    if (m.triangles.empty() || !test(mat)) continue;
    if (!r.names.empty()) r.names += ", ";
    r.names += "'" + mat.name + "'";
    r.inView = r.inView || meshInView(scene, m);
  }
  return r;
}

}  // namespace

EffectPlan planEffects(const Scene& scene, const Settings& settings) {
  refusePointClouds(scene, "vct");
  const VctSettings& s = settings.vct;
  EffectPlan p;
  p.full = settings.planMode == PlanMode::full;
  const std::string full = "plan.mode=full computes it anyway";
  p.dark = scene.unlit() && !p.full;

  p.lightStage(StageId::common_voxelize, true,
               "surfaces -> albedo, normal, opacity volumes; in a sequence, redone (in part when "
               "few meshes moved) only when geometry moves");
  planVoxelSums(p, settings, "");
  const MeshesWith emitters = meshesWith(scene, [](const Material& m) { return m.emissive(); });
  p.effect("emission volume", Effect::emission, p.full || !emitters.names.empty(),
           !emitters.names.empty() ? "emissive material " + emitters.names
           : p.full                ? "no emissive material; " + full
                                   : "no emissive material");
  finishVoxelSums(p);

  int shadowLights = 0;
  for (const Light& l : scene.lights) shadowLights += l.castsShadows ? 1 : 0;
  // Under emitters.mode=area_lights every emissive triangle is a light with a shadow cone.
  const size_t areaLights = areaLightCount(scene, s.emitters);
  std::ostringstream lights;
  lights << scene.lights.size() << " analytic light(s)";
  if (areaLights > 0)
    lights << " and " << areaLights << " emissive triangle(s) as area lights (emitters.mode)";
  else if (!emitters.names.empty())
    lights << " and emissive surfaces"
           << (s.emitters == EmitterLighting::automatic
                   ? " (emitters.mode=auto: more than " + std::to_string(kMaxAreaLights) +
                         " emissive triangles, in the voxels)"
                   : "");
  lights << " -> radiance per voxel";
  p.lightStage(StageId::vct_light_voxels, true, lights.str());
  p.lightStage(StageId::vct_mip, true, settingValue(settings, "mip.mode") + " pyramid (mip.mode)");
  p.set(Effect::isotropic, s.mip == MipMode::isotropic);
  p.set(Effect::anisotropic, s.mip == MipMode::anisotropic);
  std::ostringstream bounce;
  bounce << "bounce.count=" << s.bounceCount
         << (s.bounceCount > 0
                 ? ": diffuse cones from every voxel, then the pyramid again, per bounce"
                 : ": the first bounce only (the pixels' diffuse cones)");
  p.lightStage(StageId::vct_bounce, s.bounceCount > 0, bounce.str());
  p.lightStage(StageId::common_gbuffer, true, "the surface each pixel sees");

  p.lightStage(StageId::vct_trace_cones, true, "per pixel");
  std::ostringstream diffuse;
  diffuse << diffuseCones(s.cones).size() << " diffuse cones ("
          << settingValue(settings, "cones.set") << ", " << settingValue(settings, "cones.diffuse")
          << ")";
  p.note("diffuse cones", !p.dark, diffuse.str());
  std::ostringstream shadow;
  if (scene.lights.empty() && areaLights == 0)
    shadow << "no analytic or area lights";
  else
    shadow << shadowLights + int(areaLights) << " of " << scene.lights.size() + areaLights
           << " light(s) cast shadows: one cone each";
  p.note("shadow cones", shadowLights > 0 || areaLights > 0, shadow.str());
  const MeshesWith glossy = meshesWith(scene, [](const Material& m) { return m.glossy(); });
  p.effect("specular cone", Effect::specular, p.full || glossy.inView,
           glossy.inView          ? "glossy material " + glossy.names + " in view"
           : p.full               ? "no glossy material in view; " + full
           : glossy.names.empty() ? "no glossy material"
                                  : "glossy material " + glossy.names + " outside the view");
  const bool askedAo = s.ambientOcclusion == AmbientOcclusion::on;
  p.effect("ambient occlusion", Effect::ambient_occlusion, p.full || askedAo,
           askedAo  ? "ao.mode=on"
           : p.full ? "ao.mode=off, so not applied; " + full
                    : "ao.mode=off");
  p.stage(StageId::vct_compose, true,
          p.dark ? "the black image alone" : "material x light terms + emission");
  return p;
}

// No sparse buffers: its dumps are dense grids and images.
SparseLayouts sparseLayouts(const BufferSet&, const GridSpec&) {
  return {};
}

// trace_cones' terms; compose darkens the indirect diffuse term with AO only under ao.mode=on.
LightTermBuffers lightTerms(const Settings& settings) {
  using enum BufferId;
  LightTermBuffers b{vct_trace_cones_direct_diffuse, vct_trace_cones_direct_specular,
                     vct_trace_cones_indirect_diffuse, vct_trace_cones_indirect_specular,
                     std::nullopt};
  if (settings.vct.ambientOcclusion == AmbientOcclusion::on)
    b.ambientOcclusion = vct_trace_cones_ambient_occlusion;
  return b;
}

}  // namespace voxgi::vct
