// The comparison registry: for every buffer, the metric, the tolerance and why.
#pragma once

#include <string>
#include <string_view>

namespace voxgi::validation {

// max_rel: |gpu - cpu| <= tolerance * the largest |component| of the element on either backend,
// so a colour channel near zero is judged against the element's magnitude, not its own.
enum class Metric { exact, max_ulp, max_abs, max_rel };

struct Comparison {
  std::string_view stage;
  std::string_view buffer;
  Metric metric;
  double tolerance;
  std::string_view reason;
  std::string describe() const;  // "exact", "max 3 ULP", "max |gpu-cpu| 1e-06", "max rel 1e-05"
};

// The registered comparison of a buffer; throws std::out_of_range for an unknown one.
const Comparison& comparisonFor(std::string_view stage, std::string_view buffer);

}  // namespace voxgi::validation
