#include "tools/metrics_json.h"

#include <cmath>

namespace voxgi::tools {

nlohmann::json numberOrNull(double v) {
  return std::isnan(v) ? nlohmann::json() : nlohmann::json(v);
}

nlohmann::json metricsJson(const reference::ImageMetrics& m) {
  return {
      {"rmse", numberOrNull(m.rmse)},
      {"rel_mse", numberOrNull(m.relMse)},
      {"mare", numberOrNull(m.mare)},
      {"ssim", numberOrNull(m.ssim)},
      {"energy", {numberOrNull(m.energy.r), numberOrNull(m.energy.g), numberOrNull(m.energy.b)}}};
}

}  // namespace voxgi::tools
