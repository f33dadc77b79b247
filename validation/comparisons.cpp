#include "validation/comparisons.h"

#include <sstream>

namespace voxgi::validation {
namespace {

#define VOXGI_COMPARISON(owner, stage, buffer, kind, tolerance, ties, widening, reason) \
  Comparison{BufferId::owner##_##stage##_##buffer,                                      \
             Metric::kind,                                                              \
             tolerance,                                                                 \
             Ties::ties,                                                                \
             Widening::widening,                                                        \
             reason},
constexpr Comparison kComparisons[] = {
#include "validation/comparisons.inc"
};

// A comparison names a declared buffer or does not compile; this checks there is one for every
// buffer, in declaration order, so comparisonFor can index.
constexpr bool everyBufferHasItsComparison() {
  constexpr size_t buffers = [] {
    size_t n = 0;
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning) ++n;
#include "common/stages.inc"
    return n;
  }();
  if (std::size(kComparisons) != buffers) return false;
  for (size_t i = 0; i < std::size(kComparisons); ++i)
    if (static_cast<size_t>(kComparisons[i].buffer) != i) return false;
  return true;
}
static_assert(everyBufferHasItsComparison(),
              "validation/comparisons.inc must list one comparison per buffer of "
              "common/stages.inc, in the same order");

// The stage of each buffer, in declaration order (the order of kComparisons).
constexpr StageId kBufferStages[] = {
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning) \
  StageId::owner##_##stage,
#include "common/stages.inc"
};

// The scalar type of each buffer, in declaration order.
constexpr ScalarType kBufferTypes[] = {
#define VOXGI_TECHNIQUE(technique, image_stage, image, summary)
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning) ScalarType::type,
#include "common/stages.inc"
};

// A buffer stored as halves (f16) compares exactly or widens by their rounding; half_rounding names
// nothing else.
constexpr bool halvesWidenByTheirRounding() {
  for (size_t i = 0; i < std::size(kComparisons); ++i) {
    const Comparison& c = kComparisons[i];
    const bool halves = kBufferTypes[i] == ScalarType::f16;
    const bool exact = c.metric == Metric::exact && c.widening == Widening::none;
    if (halves ? !(exact || c.widening == Widening::half_rounding)
               : c.widening == Widening::half_rounding)
      return false;
  }
  return true;
}
static_assert(halvesWidenByTheirRounding(),
              "validation/comparisons.inc: an f16 buffer's comparison is exact or widens by "
              "half_rounding, and only an f16 buffer's widens so");

// The diff classifies an element once for all the buffers of its stage.
constexpr bool aStageHasOneTieRule() {
  for (size_t i = 1; i < std::size(kComparisons); ++i)
    if (kBufferStages[i] == kBufferStages[i - 1] &&
        kComparisons[i].ties != kComparisons[i - 1].ties)
      return false;
  return true;
}
static_assert(aStageHasOneTieRule(),
              "validation/comparisons.inc: every buffer of a stage must name the same ties");

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
  if (widening == Widening::half_rounding) s << " + 1 f16 ULP";
  return s.str();
}

const Comparison& comparisonFor(BufferId buffer) {
  return kComparisons[static_cast<size_t>(buffer)];
}

}  // namespace voxgi::validation
