// The sparse voxel octree's effect planner (docs/effect-plan.md).
#include <sstream>

#include "common/lights.h"
#include "common/error.h"
#include "common/svo/propagate.h"
#include "common/svo/tree_depth.h"
#include "common/technique.h"

namespace voxgi::svo {
namespace {

// Names of the materials of meshes and clouds that pass `test`.
template <class Test>
std::string materialsWith(const Scene& scene, Test test) {
  std::string names;
  auto add = [&](uint32_t material) {
    const Material& m = scene.materials.at(material);
    const std::string name = "'" + m.name + "'";
    if (!test(m) || names.find(name) != std::string::npos) return;
    names += (names.empty() ? "" : ", ") + name;
  };
  for (const Mesh& m : scene.meshes)
    if (!m.triangles.empty()) add(m.material);
  for (const PointCloud& c : scene.pointClouds)
    if (c.size() > 0) add(c.material);
  return names;
}

}  // namespace

EffectPlan planEffects(const Scene& scene, const Settings& settings) {
  const SvoSettings& s = settings.svo;
  const int depth = treeDepth(scene);
  EffectPlan p;
  p.full = settings.planMode == PlanMode::full;
  p.dark = scene.unlit() && !p.full;
  size_t points = 0, triangles = 0;
  for (const PointCloud& c : scene.pointClouds) points += c.size();
  for (const Mesh& m : scene.meshes) triangles += m.triangles.size();
  std::ostringstream build;
  build << "depth " << depth << " (2^" << depth
        << " leaves a side, grid.resolution): " << scene.pointClouds.size() << " point cloud(s) of "
        << points << " point(s)";
  if (triangles > 0)
    build << ", " << triangles << " triangle(s) sampled at " << s.meshDensity
          << " points per leaf face (build.mesh_density)";
  p.lightStage(StageId::svo_build, true, build.str());
  // Every later stage reads the leaves decoded from the sums; the sums are the words the backends'
  // builds compare exactly.
  p.effect("fixed-point leaf sums", Effect::leaf_sums, settings.inspect || p.full,
           settings.inspect ? "voxgi diff and dump compare the builds' sums word for word"
           : p.full         ? "plan.mode=full keeps them beside the leaves"
                            : "decoded into the leaves' halves and released");
  std::ostringstream frames;
  const size_t areaLights = areaLightCount(scene, settings.vct.emitters);
  frames << scene.lights.size() << " analytic light(s)";
  if (areaLights > 0)
    frames << " and " << areaLights << " emissive triangle(s) as area lights (emitters.mode)";
  frames << " injected with " << settingValue(settings, "voxel_shadow.mode") << " voxel shadows; "
         << s.frames << " frame(s) (propagate.frames)"
         << (s.clearEachFrame == SvoToggle::on ? " each gathering from the direct light alone"
                                               : ", one more bounce each")
         << (carriesLight(settings)
                 ? ", in a sequence from the light the frame before gathered (propagate.carry)"
                 : "")
         << "; the last frame's gathered light as leaf bricks";
  p.lightStage(StageId::svo_propagate, true, frames.str());
  p.carry(StageId::svo_propagate, carriesLight(settings));
  // Shading reads the gathered light from its bricks; the per-leaf light is compared.
  p.effect("per-leaf direct and gathered light", Effect::leaf_light, settings.inspect || p.full,
           settings.inspect ? "voxgi diff and dump compare the backends' injection and gather"
           : p.full         ? "plan.mode=full keeps them beside the gathered bricks"
                            : "the gathered bricks hold what shading reads");
  p.lightStage(StageId::svo_mip, true,
               "the last frame's radiance up the tree (svo.first_step=" +
                   settingValue(settings, "svo.first_step") + ")");
  p.lightStage(StageId::common_gbuffer, true,
               "the surface each pixel sees (point clouds as discs)");
  const std::string emitters = materialsWith(scene, [](const Material& m) { return m.emissive(); });
  p.effect("emission per pixel", Effect::emission, p.full || !emitters.empty(),
           emitters.empty() ? "no emissive material" : "emissive material " + emitters);
  p.stage(
      StageId::svo_shade, true,
      p.dark
          ? "the black image alone"
          : "shadow cones and the specular cone through the tree, diffuse light from the leaves (" +
                settingValue(settings, "shade.filter") + ")");
  const std::string glossy = materialsWith(scene, [](const Material& m) { return m.glossy(); });
  p.effect("specular cone", Effect::specular, p.full || !glossy.empty(),
           !glossy.empty() ? "glossy material " + glossy
           : p.full        ? "no glossy material; plan.mode=full computes it anyway"
                           : "no glossy material");
  return p;
}

// shade's terms.
LightTermBuffers lightTerms(const Settings&) {
  using enum BufferId;
  return {svo_shade_direct_diffuse, svo_shade_direct_specular, svo_shade_indirect_diffuse,
          svo_shade_indirect_specular, std::nullopt};
}

}  // namespace voxgi::svo
