#include "common/effect_plan.h"

#include <sstream>

#include "common/camera_geometry.h"
#include "common/cone_sets.h"

namespace voxgi {
namespace {

// The value of `key` as settingValues prints it ("cones.set" -> "equal7").
std::string settingValue(const Settings& settings, const std::string& key) {
  for (const std::string& kv : settingValues(settings))
    if (kv.compare(0, key.size() + 1, key + "=") == 0) return kv.substr(key.size() + 1);
  return {};
}

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

bool EffectPlan::runs(std::string_view stage) const {
  return stage != "bounce" || bounces > 0;
}

bool meshInView(const Scene& scene, const Mesh& mesh) {
  if (mesh.triangles.empty()) return false;
  // The camera both gbuffer backends render with, in voxel-local coordinates.
  const CameraRays cam = cameraRays(scene);
  const double tanY = cam.tanHalfFov, tanX = tanY * double(cam.aspect);
  glm::dvec3 lo(mesh.positions[mesh.triangles[0].x]), hi(lo);
  for (const glm::uvec3& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      lo = glm::min(lo, mesh.positions[t[c]]);
      hi = glm::max(hi, mesh.positions[t[c]]);
    }
  // Counts, per frustum plane, the box corners outside it; a plane with all 8 outside hides it.
  int outside[5] = {};
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                       (corner & 4) ? hi.z : lo.z);
    const glm::dvec3 d = scene.grid.toVoxel(p) - glm::dvec3(cam.origin);
    const double x = glm::dot(d, glm::dvec3(cam.right)), y = glm::dot(d, glm::dvec3(cam.up)),
                 z = glm::dot(d, glm::dvec3(cam.forward));
    // A relative margin keeps the test conservative under the camera's float rounding.
    const double slack = 1e-4 * glm::length(d);
    outside[0] += z < -slack;
    outside[1] += x > z * tanX + slack;
    outside[2] += -x > z * tanX + slack;
    outside[3] += y > z * tanY + slack;
    outside[4] += -y > z * tanY + slack;
  }
  for (int count : outside)
    if (count == 8) return false;
  return true;
}

EffectPlan planEffects(const Scene& scene, const Settings& settings) {
  EffectPlan p;
  p.full = settings.planMode == PlanMode::full;
  p.mip = settings.mip;
  p.bounces = settings.bounceCount;
  auto& items = p.items;
  const auto add = [&items](std::string name, bool in, std::string why) {
    items.push_back({std::move(name), in, std::move(why)});
  };
  const std::string full = "plan.mode=full computes it anyway";

  add("voxelize", true,
      "surfaces -> albedo, normal, opacity volumes; the geometry is static, so one voxelization "
      "serves every frame and any relighting");
  const MeshesWith emitters = meshesWith(scene, [](const Material& m) { return m.emissive(); });
  p.emission = p.full || !emitters.names.empty();
  add("  emission volume", p.emission,
      !emitters.names.empty() ? "emissive material " + emitters.names
      : p.full                ? "no emissive material; " + full
                              : "no emissive material");

  int shadowLights = 0;
  for (const Light& l : scene.lights) shadowLights += l.castsShadows ? 1 : 0;
  std::ostringstream lights;
  lights << scene.lights.size() << " analytic light(s)"
         << (emitters.names.empty() ? "" : " and emissive surfaces") << " -> radiance per voxel";
  add("light_voxels", true, lights.str());
  add("mip", true, settingValue(settings, "mip.mode") + " pyramid (mip.mode)");
  std::ostringstream bounce;
  bounce << "bounce.count=" << p.bounces
         << (p.bounces > 0 ? ": diffuse cones from every voxel, then the pyramid again, per bounce"
                           : ": the first bounce only (the pixels' diffuse cones)");
  add("bounce", p.bounces > 0, bounce.str());
  add("gbuffer", true, "the surface each pixel sees");

  add("trace_cones", true, "per pixel");
  std::ostringstream diffuse;
  diffuse << diffuseCones(settings.cones).size() << " diffuse cones ("
          << settingValue(settings, "cones.set") << ", " << settingValue(settings, "cones.diffuse")
          << ")";
  add("  diffuse cones", true, diffuse.str());
  p.shadowLights = shadowLights;
  std::ostringstream shadow;
  if (scene.lights.empty())
    shadow << "no analytic lights";
  else
    shadow << shadowLights << " of " << scene.lights.size()
           << " light(s) cast shadows: one cone each";
  add("  shadow cones", shadowLights > 0, shadow.str());
  const MeshesWith glossy = meshesWith(scene, [](const Material& m) { return m.glossy(); });
  p.specular = p.full || glossy.inView;
  add("  specular cone", p.specular,
      glossy.inView          ? "glossy material " + glossy.names + " in view"
      : p.full               ? "no glossy material in view; " + full
      : glossy.names.empty() ? "no glossy material"
                             : "glossy material " + glossy.names + " outside the view");
  const bool askedAo = settings.ambientOcclusion == AmbientOcclusion::on;
  p.ambientOcclusion = p.full || askedAo;
  add("  ambient occlusion", p.ambientOcclusion,
      askedAo  ? "ao.mode=on"
      : p.full ? "ao.mode=off, so not applied; " + full
               : "ao.mode=off");
  add("compose", true, "material x light terms + emission");
  return p;
}

}  // namespace voxgi
