// The comparison registry: for every buffer, the metric, the tolerance and why.
#pragma once

#include <string>
#include <string_view>

#include "common/stage_list.h"

namespace voxgi::validation {

// max_rel: |gpu - cpu| <= tolerance * the largest |component| of the element on either backend,
// so a colour channel near zero is judged against the element's magnitude, not its own.
enum class Metric { exact, max_ulp, max_abs, max_rel };

struct Comparison {
  BufferId buffer;
  Metric metric;
  double tolerance;
  std::string_view reason;
  std::string describe() const;  // "exact", "max 3 ULP", "max |gpu-cpu| 1e-06", "max rel 1e-05"
};

// The registered comparison of a buffer (every declared buffer has one).
const Comparison& comparisonFor(BufferId buffer);

}  // namespace voxgi::validation
