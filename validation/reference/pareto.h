// The Pareto front of (time, error) points, for `voxgi study`.
#pragma once

#include <cstddef>
#include <vector>

namespace voxgi::reference {

// True for each point that no other point beats: no other is at most as slow and at most as wrong
// and strictly better in one. Equal points are all on the front.
std::vector<bool> paretoFront(const std::vector<double>& seconds, const std::vector<double>& error);

}  // namespace voxgi::reference
