// Image metrics as the JSON of `voxgi compare --json` and `voxgi study`, and as voxgi.compare's
// dict in Python: one set of names.
#pragma once

#include <nlohmann/json.hpp>

#include "validation/reference/image_metrics.h"

namespace voxgi::tools {

// JSON has no NaN: an undefined metric (a black reference, a term black in it) is null.
nlohmann::json numberOrNull(double v);

// rmse, rel_mse, mare, ssim and energy (per channel).
nlohmann::json metricsJson(const reference::ImageMetrics& m);

}  // namespace voxgi::tools
