// The comparison registry: for every buffer, the metric, the tolerance and why.
#pragma once

#include <string>
#include <string_view>

namespace voxgi::validation {

enum class Metric { exact, max_ulp, max_abs };

struct Comparison {
  std::string_view stage;
  std::string_view buffer;
  Metric metric;
  double tolerance;
  std::string_view reason;
  std::string describe() const;  // "exact", "max 3 ULP", "max |gpu-cpu| 1e-06"
};

// The registered comparison of a buffer; throws std::out_of_range for an unknown one.
const Comparison& comparisonFor(std::string_view stage, std::string_view buffer);

}  // namespace voxgi::validation
