#include "common/effect_plan.h"

#include <stdexcept>

#include "common/camera_geometry.h"
#include "common/error.h"

namespace voxgi {

void refusePointClouds(const Scene& scene, std::string_view technique) {
  if (scene.pointClouds.empty()) return;
  throw InputError(scene.file, "point_clouds",
                   std::string(technique) + " renders triangle meshes; the point cloud " +
                       scene.pointClouds.front().name + " renders with --technique svo or path");
}

const char* const kDarkReason =
    "nothing emits light: the image is black without it (plan.mode=full runs it anyway)";

void EffectPlan::stage(StageId id, bool runs, std::string why) {
  const StageSpec& spec = stageSpec(id);
  items.push_back({std::string(spec.name), runs, std::move(why), &spec});
}

void EffectPlan::lightStage(StageId id, bool runs, std::string why) {
  stage(id, runs && !dark, dark ? kDarkReason : std::move(why));
}

void EffectPlan::effect(std::string name, Effect e, bool in, std::string why) {
  set(e, in);
  note(std::move(name), in, std::move(why));
}

void EffectPlan::note(std::string name, bool in, std::string why) {
  items.push_back({"  " + std::move(name), in, std::move(why), nullptr});
}

bool EffectPlan::runs(StageId id) const {
  for (const PlanItem& item : items)
    if (item.stage != nullptr && item.stage->id == id) return item.in;
  return false;
}

bool EffectPlan::decides(StageId id) const {
  for (const PlanItem& item : items)
    if (item.stage != nullptr && item.stage->id == id) return true;
  return false;
}

std::string EffectPlan::whySkipped(StageId id) const {
  for (const PlanItem& item : items)
    if (item.stage != nullptr && item.stage->id == id) return item.in ? std::string() : item.why;
  return "the plan does not list it";
}

bool bufferNeeded(const BufferSpec& spec, const EffectPlan& plan) {
  return plan.runs(spec.stage) && plan.on(spec.need);
}

void planVoxelSums(EffectPlan& p, const Settings& settings, const std::string& reader) {
  p.effect("voxel sums", Effect::voxel_sums,
           settings.inspect || p.full || !reader.empty() || settings.sequence,
           settings.inspect  ? "voxgi diff and dump compare the backends' sums word for word"
           : p.full          ? "plan.mode=full keeps them beside the volumes"
           : !reader.empty() ? reader + " reads them"
           : settings.sequence
               ? "a sequence: where meshes move, the next frame updates them in part"
               : "resolved into the volumes and released (the CPU holds them only in the "
                 "blocks of 8^3 voxels the surface reaches)");
}

void finishVoxelSums(EffectPlan& p) {
  p.set(Effect::emission_sum, p.on(Effect::voxel_sums) && p.on(Effect::emission));
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

void EffectPlan::carry(StageId id, bool carries) {
  if (carries && (stageSpec(id).reads & stage_reads::history) == 0)
    throw std::logic_error(stageSpec(id).qualifiedName() +
                           " carries a state across frames but does not declare the history "
                           "among what it reads (common/stages.inc)");
  carries_.set(size_t(id), carries);
}

bool EffectPlan::sameDecisions(const EffectPlan& other) const {
  if (full != other.full || dark != other.dark || seriesLength != other.seriesLength ||
      maps != other.maps || effects_ != other.effects_ || carries_ != other.carries_ ||
      items.size() != other.items.size())
    return false;
  for (size_t i = 0; i < items.size(); ++i)
    if (items[i].name != other.items[i].name || items[i].in != other.items[i].in) return false;
  return true;
}

}  // namespace voxgi
