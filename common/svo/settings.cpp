// The sparse voxel octree's --set keys and presets. The cone and light keys are voxel cone
// tracing's own (the same fields, Settings::vct): the octree traces with the shared cone kernel,
// so a cone set or shadow model means the same thing for both techniques.
#include "common/technique.h"

namespace voxgi::svo {

const std::vector<Param>& params() {
  constexpr auto svo = &Settings::svo;
  static const std::vector<Param> table = [] {
    std::vector<Param> out{
        number<svo>("build.mesh_density", &SvoSettings::meshDensity, 0.25f, 64.0f,
                    "points sampled per leaf face of mesh area (meshes in an svo scene become "
                    "points, area-uniform)"),
        number<svo>("propagate.frames", &SvoSettings::frames, 0, 256,
                    "progressive frames: each gathers one more diffuse bounce at every leaf from "
                    "the last (0: direct light only)"),
        choice<svo>("propagate.clear_each_frame", &SvoSettings::clearEachFrame, {"off", "on"},
                    "every frame gathers from the direct light alone: exactly one bounce"),
        choice<svo>("propagate.carry", &SvoSettings::carry, {"off", "on"},
                    "in a sequence, each frame's gathers start from the frame before's gathered "
                    "light, so bounces build up over the frames rendered and lag the scene "
                    "(Salm 2015, 4.4.3); propagate then runs every frame until its light settles"),
        choice<svo>("svo.first_step", &SvoSettings::firstStep, {"plain", "ndf"},
                    "the first mip step composites the leaves as the dense mip does, or weights "
                    "each by its normal distribution per face (Salm 2015, 4.4.2)"),
        number<svo>("build.seed", &SvoSettings::seed, 0, 1 << 30,
                    "seed of the points sampled on meshes"),
        choice<svo>("shade.filter", &SvoSettings::shadeFilter, {"trilinear", "tricubic"},
                    "how shading samples the leaves' gathered light: trilinearly, or with a cubic "
                    "B-spline over 4^3 leaves (smoother, 8 trilinear samples)"),
    };
    // Voxel cone tracing's keys that the octree's stages read; svo's shade traces the diffuse
    // cones of every pixel (cones.diffuse_scale is trace_cones').
    for (Param& p :
         vct::kernelParams({"emitters", "cones", "shadow", "specular", "light", "voxel_shadow"}))
      if (p.key != "cones.diffuse_scale") out.push_back(std::move(p));
    return out;
  }();
  return table;
}

const std::vector<Preset>& presets() {
  static const std::vector<Preset> table{{"default", {}}};
  return table;
}

const std::vector<Variant>& variants() {
  static const std::vector<Variant> table;
  return table;
}

}  // namespace voxgi::svo
