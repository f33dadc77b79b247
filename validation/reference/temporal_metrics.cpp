#include "validation/reference/temporal_metrics.h"

#include <cmath>
#include <limits>

namespace voxgi::reference {

TemporalMetrics compareChanges(const Image& testA, const Image& testB, const Image& referenceA,
                               const Image& referenceB, const std::vector<uint8_t>& mask,
                               const MetricScale& scale, const std::optional<Image>& varianceA,
                               const std::optional<Image>& varianceB) {
  const bool noise = varianceA && varianceB;
  double error = 0.0, held = 0.0, variance = 0.0;
  size_t values = 0;
  for (size_t e = 0; e < referenceB.pixels.size(); ++e) {
    if (!mask.empty() && mask[e] == 0) continue;
    for (int c = 0; c < 3; ++c) {
      const double u2 = scale.unit[c] * scale.unit[c];
      const double t = double(testB.pixels[e][c]) - double(testA.pixels[e][c]);
      const double r = double(referenceB.pixels[e][c]) - double(referenceA.pixels[e][c]);
      error += (t - r) * (t - r) / u2;
      held += r * r / u2;
      if (noise)
        variance += (double(varianceA->pixels[e][c]) + double(varianceB->pixels[e][c])) / u2;
      ++values;
    }
  }
  const double n = double(values == 0 ? 1 : values);
  return {std::sqrt(error / n), std::sqrt(held / n),
          noise ? std::sqrt(variance / n) : std::numeric_limits<double>::quiet_NaN()};
}

}  // namespace voxgi::reference
