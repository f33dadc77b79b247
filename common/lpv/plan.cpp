// Light propagation volumes' effect planner (docs/effect-plan.md).
#include <sstream>

#include "common/lights.h"
#include "common/lpv/rsm.h"
#include "common/lpv/sh_buffers.h"
#include "common/technique.h"

namespace voxgi::lpv {

EffectPlan planEffects(const Scene& scene, const Settings& settings) {
  refusePointClouds(scene, "lpv");
  const LpvSettings& s = settings.lpv;
  EffectPlan p;
  p.full = settings.planMode == PlanMode::full;
  p.dark = scene.unlit() && !p.full;
  std::string emitters;
  for (const Mesh& m : scene.meshes) {
    const Material& mat = scene.materials.at(m.material);
    if (m.triangles.empty() || !mat.emissive()) continue;
    emitters += (emitters.empty() ? "'" : ", '") + mat.name + "'";
  }
  // Emissive triangles as area lights (emitters.mode): direct light per pixel, their RSMs' texels
  // the VPLs of their first bounce; else VPLs of their own, as [Martin 2012] injects them.
  const size_t areaLights = areaLightCount(scene, settings.vct.emitters);
  p.lightStage(
      StageId::common_voxelize, true,
      s.occlusion == LpvOcclusion::on
          ? "surface area and normals per voxel -> the geometry volume"
          : "propagate.occlusion=off, but the voxel volumes are the scene's grid for every "
            "technique");
  planVoxelSums(
      p, settings,
      s.occlusion == LpvOcclusion::on || p.full ? "inject_geometry (the geometry volume)" : "");
  const int views = rsmViewCount(scene, settings);
  std::ostringstream rsm;
  if (views == 0)
    rsm << "no analytic lights" << (emitters.empty() ? "" : " and emitters.mode=voxels");
  else
    rsm << scene.lights.size() << " analytic light(s) and " << areaLights
        << " emissive triangle(s) as area lights (emitters.mode): " << views << " view(s) of "
        << s.rsmResolution << "^2 texels (rsm.resolution)";
  p.lightStage(StageId::lpv_rsm, views > 0, rsm.str());
  p.maps = glm::ivec2(s.rsmResolution, views);
  std::string sources =
      emitters.empty() || areaLights > 0 ? "" : "VPLs on emissive material " + emitters;
  if (views > 0) sources += std::string(sources.empty() ? "" : " and ") + "a VPL per RSM texel";
  p.lightStage(StageId::lpv_inject, true,
               sources.empty() ? "no emissive material and no analytic light: the volume stays dark"
                               : sources);
  const ShBuffers sh = shBuffers(s);
  p.set(sh.coefficients, true);
  const bool fromRsm = s.geometry == LpvGeometry::rsm;
  const std::string source =
      !fromRsm    ? "voxelize's surfaces"
      : views > 0 ? "the RSM texels' surfaces (inject_geometry.blockers=rsm)"
                  : "inject_geometry.blockers=rsm, but no analytic light: nothing blocks";
  p.lightStage(StageId::lpv_inject_geometry, s.occlusion == LpvOcclusion::on || p.full,
               s.occlusion == LpvOcclusion::on
                   ? "blockers for propagate (propagate.occlusion=on) from " + source
               : p.full ? "propagate.occlusion=off; plan.mode=full computes it"
                        : "propagate.occlusion=off");
  p.set(Effect::rsm_blockers, fromRsm);
  const int steps = propagationSteps(s, scene.grid.resolution);
  std::ostringstream why;
  why << steps << " steps over " << s.directionCount() << " directions, " << s.bands
      << " SH bands, " << settingValue(settings, "lpv.storage") << " volumes ("
      << (s.steps > 0 ? "propagate.steps" : "propagate.steps=0: half the grid's resolution") << ")";
  p.lightStage(StageId::lpv_propagate, true, why.str());
  p.seriesLength = steps + 1;
  p.set(Effect::f16, s.storage == LpvStorage::f16);
  const bool history = s.history == LpvToggle::on || settings.inspect || p.full;
  p.effect("every step's volume", sh.history, history,
           s.history == LpvToggle::on ? "propagate.history=on"
           : settings.inspect         ? "voxgi diff and dump keep every step"
           : p.full                   ? "propagate.history=off; plan.mode=full keeps them"
                                      : "propagate.history=off");
  p.lightStage(StageId::common_gbuffer, true, "the surface each pixel sees");
  // One effect for the voxel and pixel emission buffers: the voxels' is unused here, and costs
  // only a volume next to the sums voxelize keeps anyway.
  p.effect("emission per pixel", Effect::emission, p.full || !emitters.empty(),
           emitters.empty() ? "no emissive material" : "emissive material " + emitters);
  finishVoxelSums(p);
  p.set(Effect::direct_light, views > 0 || p.full);
  p.stage(StageId::lpv_shade, true,
          p.dark ? "the black image alone"
          : views > 0
              ? "irradiance from the accumulated volume, direct light with the RSM depth as "
                "shadow map, x albedo + emission"
              : "irradiance from the accumulated volume x albedo + emission");
  return p;
}

// No sparse buffers: its dumps are dense grids and images.
SparseLayouts sparseLayouts(const BufferSet&, const GridSpec&) {
  return {};
}

// shade's terms: a volume's light is diffuse, so it has no indirect specular term.
LightTermBuffers lightTerms(const Settings&) {
  using enum BufferId;
  return {lpv_shade_direct_diffuse, lpv_shade_direct_specular, lpv_shade_indirect_diffuse,
          std::nullopt, std::nullopt};
}

}  // namespace voxgi::lpv
