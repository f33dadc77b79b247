// Tie classification for the voxelize stage. A voxel whose sums differ between backends is a tie
// when some triangle's contribution to it sits within float error of a decision boundary:
// - the separating-axis test: |normalised separation| <= kSatEpsilon * max(N, 1) voxels
//   (coordinates are floats of magnitude <= N + 1; a few operations accumulate a few ULPs);
// - a fixed-point rounding: the value to round is within 4 ULP of a half-integer.
// Everything else that differs is a bug. See docs/stages/voxelize.md.
#include <cmath>

#include "shaders/shared/voxelize_kernel.h"
#include "validation/diff.h"

namespace voxgi::validation {
namespace {

using shared::VoxelTriangle;

constexpr float kSatEpsilon = 64.0f * 0x1p-24f;

bool nearHalf(float x) {
  const float frac = x - std::floor(x);
  return std::abs(frac - 0.5f) <= 4.0f * 0x1p-23f * std::max(std::abs(x), 1.0f);
}

bool contributionNearHalf(const VoxelTriangle& t, float weightValue) {
  if (nearHalf(weightValue)) return true;
  const float w = std::floor(weightValue + 0.5f);
  for (int c = 0; c < 3; ++c)
    if (nearHalf(w * t.albedo[c]) || nearHalf(w * t.normal[c]) || nearHalf(w * t.emission[c]))
      return true;
  return false;
}

bool conservativeTie(const VoxelTriangle& t, const glm::ivec3& v, float satEpsilon) {
  const glm::vec3 centre = glm::vec3(v) + glm::vec3(0.5f);
  const glm::vec3 a = glm::vec3(t.v0) - centre, b = glm::vec3(t.v1) - centre,
                  c = glm::vec3(t.v2) - centre;
  const float s = shared::satSeparation(a, b, c, true);
  if (std::abs(s) <= satEpsilon) return true;
  if (s > 0.0f) return false;
  glm::vec3 middle;
  const float area = shared::projectedAreaInVoxel(a, b, c, t.dominantAxis, middle) * t.areaScale;
  return contributionNearHalf(t, area * shared::kWeightScale);
}

bool antialiasedTie(const VoxelTriangle& t, const glm::ivec3& v) {
  for (int i = 0; i < int(t.subdivision); ++i)
    for (int k = 0; k < shared::antialiasedRowSamples(t, i); ++k) {
      const glm::vec3 p = shared::antialiasedSample(t, shared::antialiasedRowBarycentric(t, i, k));
      const glm::ivec3 base = shared::tentBase(p);
      const glm::ivec3 d = v - base;
      if (d.x < 0 || d.y < 0 || d.z < 0 || d.x > 1 || d.y > 1 || d.z > 1) continue;
      const float w = shared::tentWeightValue(t, p, base, d.x + 2 * d.y + 4 * d.z);
      if (contributionNearHalf(t, w)) return true;
    }
  return false;
}

}  // namespace

TieClassifier voxelizeTies(const StageContext& ctx) {
  const int n = ctx.scene.grid.resolution;
  const bool antialiased = ctx.settings.voxelizeMode == VoxelizeMode::antialiased;
  const float satEpsilon = kSatEpsilon * float(std::max(n, 1));
  const auto* triangles = &ctx.triangles.triangles;
  return [=](size_t element) {
    const auto nn = size_t(n);
    const glm::ivec3 v(int(element % nn), int((element / nn) % nn), int(element / (nn * nn)));
    const float reach = antialiased ? 1.0f : satEpsilon;  // tent kernel reaches one voxel
    for (const VoxelTriangle& t : *triangles) {
      const glm::vec3 lo = glm::min(glm::vec3(t.v0), glm::min(glm::vec3(t.v1), glm::vec3(t.v2)));
      const glm::vec3 hi = glm::max(glm::vec3(t.v0), glm::max(glm::vec3(t.v1), glm::vec3(t.v2)));
      if (glm::any(glm::lessThan(hi, glm::vec3(v) - reach)) ||
          glm::any(glm::greaterThan(lo, glm::vec3(v) + 1.0f + reach)))
        continue;
      if (antialiased ? antialiasedTie(t, v) : conservativeTie(t, v, satEpsilon)) return true;
    }
    return false;
  };
}

}  // namespace voxgi::validation
