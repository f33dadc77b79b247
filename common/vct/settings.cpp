// Voxel cone tracing's --set keys and presets.
#include "common/technique.h"

namespace voxgi::vct {

const std::vector<Param>& params() {
  constexpr auto vct = &Settings::vct;
  static const std::vector<Param> table{
      choice<vct>("emitters.mode", &VctSettings::emitters, {"voxels", "area_lights", "auto"},
                  "emissive surfaces: emission in the voxels (gathered by the cones; lpv: VPLs "
                  "in the volume); or each emissive triangle an area light, exact unoccluded "
                  "with a shadow cone (lpv: its reflective shadow map), its first bounce through "
                  "the voxels (at most 64 triangles); auto: area lights up to 64 triangles"),
      choice<vct>("light.attenuation", &VctSettings::attenuation, {"cosine", "normal_weighted"},
                  "per-voxel direct light: max(n.l, 0), or Villegas' per-face weighting"),
      choice<vct>("voxel_shadow.mode", &VctSettings::voxelShadow, {"none", "hard", "soft"},
                  "voxel visibility toward each light by marching the opacity volume"),
      number<vct>("voxel_shadow.kappa", &VctSettings::voxelShadowKappa, 0.0f, 64.0f,
                  "soft voxel shadows: occlusion added per opaque voxel, divided by the distance"),
      number<vct>("voxel_shadow.offset", &VctSettings::voxelShadowOffset, 0.5f, 8.0f,
                  "voxels the shadow ray skips before testing opacity (self-shadowing)"),
      choice<vct>("mip.mode", &VctSettings::mip, {"isotropic", "anisotropic"},
                  "one averaged pyramid, or six directional pyramids"),
      choice<vct>("cones.set", &VctSettings::cones, {"equal7", "villegas6", "kahl5", "kahl9"},
                  "diffuse cone set (docs/stages/vct/trace_cones.md)"),
      choice<vct>("cones.diffuse", &VctSettings::diffuseCones, {"weighted", "first_hit"},
                  "composite each diffuse cone, or take the first surface it hits (Kahl)"),
      number<vct>("cones.diffuse_scale", &VctSettings::diffuseScale, 1, 4,
                  "the diffuse cones traced once per SCALE x SCALE block of pixels and upsampled "
                  "by depth and normal, a pixel no block's sample matches tracing its own (1: "
                  "every pixel; docs/stages/vct/trace_cones.md)"),
      number<vct>("cones.step", &VctSettings::coneStep, 0.05f, 4.0f,
                  "step along a cone as a fraction of its diameter (beta)"),
      number<vct>("cones.offset", &VctSettings::coneOffset, 0.0f, 8.0f,
                  "distance along the normal before a cone starts (self-intersection), in "
                  "cones.offset_unit"),
      choice<vct>("cones.offset_unit", &VctSettings::coneOffsetUnit, {"grid64", "voxel"},
                  "voxels of a 64^3 grid over the scene's box, never fewer voxels of the actual "
                  "grid (the start stays put in the scene above 64^3), or voxels"),
      number<vct>("cones.clearance", &VctSettings::coneClearance, 0.0f, 4.0f,
                  "largest voxel a cone samples per voxel of its height above its own surface, "
                  "so that its coarse samples leave that surface out (0: as wide as the cone)"),
      number<vct>("shadow.aperture", &VctSettings::shadowAperture, 0.1f, 120.0f,
                  "aperture of the shadow cone toward each light, degrees"),
      choice<vct>("shadow.falloff", &VctSettings::shadowFalloff, {"plain", "kahl2019"},
                  "shadow cone occlusion as sampled, or faded by smoothstep of sqrt(distance)"),
      number<vct>("shadow.strength", &VctSettings::shadowStrength, 0.01f, 1000.0f,
                  "kahl2019 shadow falloff: sqrt(distance) multiplier"),
      choice<vct>("specular.brdf", &VctSettings::specularBrdf, {"phong", "light_angle"},
                  "indirect specular as traced, or weighted by the angle to each light (Kahl)"),
      number<vct>("specular.falloff", &VctSettings::specularFalloff, 0.0f, 64.0f,
                  "light_angle specular: exponent q"),
      choice<vct>("ao.mode", &VctSettings::ambientOcclusion, {"off", "on"},
                  "ambient occlusion from the diffuse cones, multiplied into indirect diffuse"),
      number<vct>("ao.lambda", &VctSettings::ambientLambda, 0.0f, 100.0f,
                  "ambient occlusion falloff 1 / (1 + lambda r), r the cone radius in voxels"),
      number<vct>("bounce.count", &VctSettings::bounceCount, 0, 8,
                  "extra diffuse bounces, each cone-traced from every voxel "
                  "(docs/stages/vct/bounce.md)"),
  };
  return table;
}

std::vector<Param> kernelParams(std::initializer_list<std::string_view> groups) {
  std::vector<Param> out;
  for (const Param& p : params())
    for (const std::string_view group : groups)
      if (p.key.size() > group.size() && p.key.compare(0, group.size(), group) == 0 &&
          p.key[group.size()] == '.') {
        out.push_back(p);
        break;
      }
  return out;
}

const std::vector<Preset>& presets() {
  static const std::vector<Preset> table{
      {"default", {}},
      // [Kahl 2019]: direct light computed while voxelizing (no voxel shadows), glGenerateMipmap,
      // and §5.4.4's cone variants: 5 cones, first hit, smoothstep/sqrt shadows, light-angle
      // specular; the cones' offset in voxels.
      {"kahl2019",
       {"mip.mode=isotropic", "voxel_shadow.mode=none", "cones.set=kahl5",
        "cones.offset_unit=voxel", "cones.diffuse=first_hit", "shadow.falloff=kahl2019",
        "shadow.aperture=30", "specular.brdf=light_angle"}},
      // [Villegas 2017]: emission in the voxels (§2.3), normal-weighted attenuation, soft voxel
      // shadows, directional volumes, 6 cones, AO, the cones' offset in voxels (§4).
      {"villegas2017",
       {"emitters.mode=voxels", "light.attenuation=normal_weighted", "voxel_shadow.mode=soft",
        "mip.mode=anisotropic", "cones.set=villegas6", "ao.mode=on", "cones.offset_unit=voxel"}},
  };
  return table;
}

const std::vector<Variant>& variants() {
  static const std::vector<Variant> none;
  return none;
}

}  // namespace voxgi::vct
