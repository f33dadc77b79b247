// The comparison registry: for every buffer, the metric, the tolerance and why.
#pragma once

#include <string>
#include <string_view>

#include "common/stage_list.h"

namespace voxgi::validation {

// max_rel: |gpu - cpu| <= tolerance * the largest |component| of the element on either backend,
// so a colour channel near zero is judged against the element's magnitude, not its own.
enum class Metric { exact, max_ulp, max_abs, max_rel };

// Which elements outside the tolerance are ties, a documented near-boundary disagreement that
// passes (validation/diff.h's classifiers): none; within rounding of a voxel boundary
// (voxelize); on a triangle edge of the image's pixels (gbuffer) or of the maps' texels (a stage
// with a `primitive_id` buffer of maps, lpv's rsm).
// Every buffer of a stage has the same rule: an element is classified once for all of them.
enum class Ties { none, voxel_boundaries, pixel_edges, texel_edges };

// How the tolerance widens with the run: f16_steps, for a float buffer of a plan that stores half
// floats, by 2^-10 per propagation step up to the element's (a half rounding that falls the other
// way carries on each step; docs/lpv.md, T16); half_rounding, for a buffer stored as halves (f16),
// by one ULP of a half: each backend rounds its own float result, and where the two straddle a
// rounding boundary their halves are one ULP apart, at most 2^-10 of the value (2^-24 below the
// smallest normal half).
enum class Widening { none, f16_steps, half_rounding };

struct Comparison {
  BufferId buffer;
  Metric metric;
  double tolerance;
  Ties ties;
  Widening widening;
  std::string_view reason;
  std::string describe() const;  // "exact", "max 3 ULP", "max |gpu-cpu| 1e-06", "max rel 1e-05"
};

// The registered comparison of a buffer (every declared buffer has one).
const Comparison& comparisonFor(BufferId buffer);

}  // namespace voxgi::validation
