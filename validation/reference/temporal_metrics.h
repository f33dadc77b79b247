// Flicker measured against ground truth: how a sequence's change from one frame to the next
// differs from its reference's (docs/motion.md, "Temporal accuracy"). A technique that flickers
// (voxels popping as an object crosses them, a light leaking in and out) changes where the
// reference does not; one that lags changes less than the reference does.
#pragma once

#include <optional>
#include <vector>

#include "common/image.h"
#include "validation/reference/image_metrics.h"

namespace voxgi::reference {

struct TemporalMetrics {
  // sqrt(mean over kept pixels and channels of ((t_b - t_a) - (r_b - r_a))^2 / u_c^2): the RMS of
  // the difference of the two changes in units u of `scale` (the reference's mean per channel).
  double error = 0.0;
  // The same for a sequence that does not change (t_b = t_a; a black sequence scores it too):
  // the reference's own change, sqrt(mean (r_b - r_a)^2 / u_c^2).
  double held = 0.0;
  // What a perfect sequence would still measure against a Monte Carlo reference whose frames
  // have per-pixel variances var_a and var_b: sqrt(mean (var_a + var_b) / u_c^2); NaN without
  // variance images.
  double noise = 0.0;
};

// Frames a and b of the sequence under test and of the reference (all four the same size, the
// caller checks); `mask` empty or one byte per pixel, non-zero to keep it.
TemporalMetrics compareChanges(const Image& testA, const Image& testB, const Image& referenceA,
                               const Image& referenceB, const std::vector<uint8_t>& mask,
                               const MetricScale& scale,
                               const std::optional<Image>& varianceA = std::nullopt,
                               const std::optional<Image>& varianceB = std::nullopt);

}  // namespace voxgi::reference
