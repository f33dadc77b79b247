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
enum class DiffuseCones { villegas6, kahl5, equal7 };     // docs/stages/trace_cones.md
enum class DiffuseMode { composite, first_hit };          // first_hit: seed 000 §5.4.4
enum class ShadowFalloff { standard, kahl2019 };          // kahl2019: smoothstep(sqrt(t))
enum class SpecularModel { phong, kahl2019 };             // kahl2019: light-angle BRDF

struct Settings {
  VoxelizeMode voxelizeMode = VoxelizeMode::conservative;
  // light_voxels
  LightAttenuation attenuation = LightAttenuation::cosine;
  VoxelShadow voxelShadow = VoxelShadow::hard;
  float voxelShadowKappa = 1.0f;   // soft shadows: occlusion per colliding voxel, times 1/t
  float voxelShadowOffset = 1.5f;  // voxels skipped before the shadow ray tests opacity
  // mip
  MipMode mip = MipMode::anisotropic;
  // bounce
  int bounces = 0;
  // trace_cones
  DiffuseCones diffuseCones = DiffuseCones::villegas6;
  DiffuseMode diffuseMode = DiffuseMode::composite;
  float beta = 1.0f;                  // step = beta * cone diameter (at least one voxel)
  float startOffset = 1.0f;           // cone apex pushed this many voxels along the normal
  float maxDistance = 0.0f;           // voxels; 0: until the cone leaves the grid
  float specularMinAperture = 0.02f;  // radians; aperture of a mirror (very high shininess)
  float shadowAperture = 0.1f;        // radians, the shadow cone toward every light
  ShadowFalloff shadowFalloff = ShadowFalloff::standard;
  float shadowStrength = 1.0f;  // kahl2019 shadow falloff: smoothstep(0, max, sqrt(t)*strength)
  SpecularModel specularModel = SpecularModel::phong;
  float shininessFalloff = 10.0f;  // kahl2019 specular BRDF exponent q
  bool ambientOcclusion = false;
  float aoLambda = 0.1f;  // AO weight 1/(1 + lambda * r), r the cone radius in voxels
};

VoxelizeMode parseVoxelizeMode(const std::string& text);  // throws InputError
const char* voxelizeModeName(VoxelizeMode mode);

// Applies "key=value"; throws InputError naming `source` (e.g. "--set") for an unknown key, a
// malformed value or one outside the key's range.
void applySetting(Settings& settings, const std::string& assignment, const std::string& source);
// Applies a named preset: "default", "kahl2019" or "villegas2017".
void applyPreset(Settings& settings, const std::string& preset);
// The current value of every key, "key=value", in table order.
std::vector<std::string> settingValues(const Settings& settings);
// One line per key: key, default, range and meaning (for --help), and the presets.
std::string describeSettings();

}  // namespace voxgi
