// Every technique parameter a stage reads, with its default. `voxgi render --help` lists them by
// key (common/settings.cpp holds the table of keys, ranges and meanings); presets set several.
#pragma once

#include <string>
#include <vector>

namespace voxgi {

enum class VoxelizeMode { conservative, antialiased };
enum class LightAttenuation { cosine, normal_weighted };  // seed 001 §2.1
enum class VoxelShadow { none, hard, soft };              // seed 001 §2.2, §2.2.1
enum class MipMode { isotropic, anisotropic };            // seed 001 §3
enum class ConeSet { equal7, villegas6, kahl5, kahl9 };   // common/cone_sets.cpp
enum class DiffuseCones { weighted, first_hit };          // first_hit: seed 000 §5.4.4
enum class ShadowFalloff { plain, kahl2019 };    // kahl2019: seed 000 §5.4.4 smoothstep/sqrt
enum class SpecularBrdf { phong, light_angle };  // light_angle: seed 000 eq. 5.6
enum class AmbientOcclusion { off, on };         // seed 001 §4.2
enum class PlanMode { planned, full };           // common/effect_plan.h

struct Settings {
  VoxelizeMode voxelizeMode = VoxelizeMode::conservative;
  // light_voxels
  LightAttenuation attenuation = LightAttenuation::cosine;
  VoxelShadow voxelShadow = VoxelShadow::hard;
  float voxelShadowKappa = 1.0f;   // soft shadows: occlusion per colliding voxel, times 1/t
  float voxelShadowOffset = 1.5f;  // voxels skipped before the shadow ray tests opacity
  // mip
  MipMode mip = MipMode::anisotropic;
  // trace_cones
  ConeSet cones = ConeSet::equal7;
  DiffuseCones diffuseCones = DiffuseCones::weighted;
  float coneStep = 0.5f;         // beta: step = beta * cone diameter
  float coneOffset = 1.0f;       // voxels along the normal before a cone starts
  float shadowAperture = 10.0f;  // degrees
  ShadowFalloff shadowFalloff = ShadowFalloff::plain;
  float shadowStrength = 1.0f;  // Kahl's shadow_str
  SpecularBrdf specularBrdf = SpecularBrdf::phong;
  float specularFalloff = 10.0f;  // Kahl's shininess_falloff q
  AmbientOcclusion ambientOcclusion = AmbientOcclusion::off;
  float ambientLambda = 0.1f;  // AO falloff 1 / (1 + lambda r), r in voxels
  // bounce
  int bounceCount = 0;  // extra diffuse bounces cone-traced per voxel
  // full: every optional effect is computed even where the plan shows it contributes nothing
  PlanMode planMode = PlanMode::planned;
};

const char* voxelizeModeName(VoxelizeMode mode);

// Applies "key=value"; throws InputError naming `source` (e.g. "--set" or the scene file) and the
// key after `fieldPrefix` for an unknown key, a malformed value or one outside the key's range.
void applySetting(Settings& settings, const std::string& assignment, const std::string& source,
                  const std::string& fieldPrefix = "");
// Applies a named preset: "default", "kahl2019" or "villegas2017".
void applyPreset(Settings& settings, const std::string& preset);
// Defaults, then a scene file's "settings" (`file` names it in errors), the preset and the --set
// assignments: the later choice wins.
Settings resolveSettings(const std::vector<std::string>& fileSettings, const std::string& file,
                         const std::string& preset, const std::vector<std::string>& sets);
// The current value of every key, "key=value", in table order.
std::vector<std::string> settingValues(const Settings& settings);
// One line per key: key, default, range and meaning (for --help), and the presets.
std::string describeSettings();

}  // namespace voxgi
