// The sparse voxel octree's parameters (Settings::svo), with their defaults. The keys, ranges and
// meanings are in common/svo/settings.cpp; the tree's depth is log2 of grid.resolution.
#pragma once

namespace voxgi {

enum class SvoToggle { off, on };
// How the first mip step weights the isotropic leaves per face: the dense mip's compositing, or by
// their normal distribution [Salm 2015, §4.4.2] (common/svo/light_types.h, FirstStep).
enum class SvoFirstStep { plain, ndf };
// How shading samples the leaves' gathered light: trilinearly, or with a cubic B-spline over 4^3
// leaves ([Salm 2015, §4.6]'s tricubic option; [Sigg & Hadwiger 2005]).
enum class SvoShadeFilter { trilinear, tricubic };

struct SvoSettings {
  float meshDensity = 4.0f;                   // points sampled per leaf face of mesh area
  int frames = 1;                             // progressive bounces [Salm 2015, §4.4.3]
  SvoToggle clearEachFrame = SvoToggle::off;  // every frame gathers from the direct light alone
  // In a sequence, a frame's gathers start from the frame before's gathered light (by leaf), so
  // bounces build up over the frames rendered [Salm 2015, §4.4.3] (common/svo/carry.h).
  SvoToggle carry = SvoToggle::off;
  SvoFirstStep firstStep = SvoFirstStep::plain;
  int seed = 1;  // of the points sampled on meshes
  SvoShadeFilter shadeFilter = SvoShadeFilter::trilinear;
};

}  // namespace voxgi
