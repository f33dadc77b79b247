#include "validation/comparisons.h"

#include <array>
#include <sstream>
#include <stdexcept>

namespace voxgi::validation {
namespace {

#define VOXGI_COMPARISON(stage, buffer, kind, tolerance, reason) \
  Comparison{#stage, #buffer, Metric::kind, tolerance, reason},
constexpr std::array kComparisons{
#include "validation/comparisons.inc"
};
#undef VOXGI_COMPARISON

struct Name {
  std::string_view stage, buffer;
};
#define VOXGI_BUFFER(stage, buffer, type, components, shape, need, meaning) Name{#stage, #buffer},
constexpr std::array kBufferNames{
#include "common/stages.inc"
};
#undef VOXGI_BUFFER

constexpr bool everyBufferHasItsComparison() {
  if (kComparisons.size() != kBufferNames.size()) return false;
  for (size_t i = 0; i < kComparisons.size(); ++i)
    if (kComparisons[i].stage != kBufferNames[i].stage ||
        kComparisons[i].buffer != kBufferNames[i].buffer)
      return false;
  return true;
}
static_assert(everyBufferHasItsComparison(),
              "validation/comparisons.inc must list one comparison per buffer of "
              "common/stages.inc, in the same order");

}  // namespace

std::string Comparison::describe() const {
  std::ostringstream s;
  switch (metric) {
    case Metric::exact:
      s << "exact";
      break;
    case Metric::max_ulp:
      s << "max " << tolerance << " ULP";
      break;
    case Metric::max_abs:
      s << "max |gpu-cpu| " << tolerance;
      break;
    case Metric::max_rel:
      s << "max |gpu-cpu| / max |element| " << tolerance;
      break;
  }
  return s.str();
}

const Comparison& comparisonFor(std::string_view stage, std::string_view buffer) {
  for (const Comparison& c : kComparisons)
    if (c.stage == stage && c.buffer == buffer) return c;
  throw std::out_of_range("no comparison registered for " + std::string(stage) + "." +
                          std::string(buffer));
}

}  // namespace voxgi::validation
