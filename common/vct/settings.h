// Voxel cone tracing's parameters (Settings::vct), with their defaults. The keys, ranges and
// meanings are in common/vct/settings.cpp, with the presets.
#pragma once

namespace voxgi {

enum class LightAttenuation { cosine, normal_weighted };  // [Villegas 2017, §2.1]
enum class VoxelShadow { none, hard, soft };              // [Villegas 2017, §2.2, §2.2.1]
enum class MipMode { isotropic, anisotropic };            // [Villegas 2017, §3]
enum class ConeSet { equal7, villegas6, kahl5, kahl9 };   // common/cone/cone_sets.cpp
enum class DiffuseCones { weighted, first_hit };          // first_hit: [Kahl 2019, §5.4.4]
enum class ShadowFalloff { plain, kahl2019 };    // kahl2019: [Kahl 2019, §5.4.4] smoothstep/sqrt
enum class SpecularBrdf { phong, light_angle };  // light_angle: [Kahl 2019, eq. 5.6]
enum class AmbientOcclusion { off, on };         // [Villegas 2017, §4.2]
// What cones.offset counts: voxels of a 64³ grid over the scene's box (never fewer than that many
// voxels of the actual grid), or voxels of the actual grid ([Villegas 2017, §4]).
enum class ConeOffsetUnit { grid64, voxel };
// voxels: emission in the voxels, gathered by the cones ([Villegas 2017, §2.3]); area_lights: each
// emissive triangle an area light (shaders/shared/area_light.h); automatic ("auto"): area lights
// up to kMaxAreaLights emissive triangles, else voxels (common/lights.h, emittersFor)
enum class EmitterLighting { voxels, area_lights, automatic };

struct VctSettings {
  // light_voxels
  EmitterLighting emitters = EmitterLighting::automatic;
  LightAttenuation attenuation = LightAttenuation::cosine;
  VoxelShadow voxelShadow = VoxelShadow::hard;
  float voxelShadowKappa = 1.0f;   // soft shadows: occlusion per colliding voxel, times 1/t
  float voxelShadowOffset = 1.5f;  // voxels skipped before the shadow ray tests opacity
  // mip
  MipMode mip = MipMode::anisotropic;
  // trace_cones
  ConeSet cones = ConeSet::equal7;
  DiffuseCones diffuseCones = DiffuseCones::weighted;
  int diffuseScale = 1;     // the diffuse cones traced once per scale x scale pixels, upsampled
  float coneStep = 0.5f;    // beta: step = beta * cone diameter
  float coneOffset = 1.0f;  // along the normal before a cone starts, in coneOffsetUnit
  ConeOffsetUnit coneOffsetUnit = ConeOffsetUnit::grid64;
  float coneClearance = 0.0f;    // sampled voxel size per voxel of height above the surface; 0: off
  float shadowAperture = 10.0f;  // degrees
  ShadowFalloff shadowFalloff = ShadowFalloff::plain;
  float shadowStrength = 1.0f;  // Kahl's shadow_str
  SpecularBrdf specularBrdf = SpecularBrdf::phong;
  float specularFalloff = 10.0f;  // Kahl's shininess_falloff q
  AmbientOcclusion ambientOcclusion = AmbientOcclusion::off;
  float ambientLambda = 0.1f;  // AO falloff 1 / (1 + lambda r), r in voxels
  // bounce
  int bounceCount = 0;  // extra diffuse bounces cone-traced per voxel
};

}  // namespace voxgi
