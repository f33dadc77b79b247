#include "validation/reference/pareto.h"

namespace voxgi::reference {

std::vector<bool> paretoFront(const std::vector<double>& seconds,
                              const std::vector<double>& error) {
  // Quadratic, for the tens to hundreds of points a study has.
  std::vector<bool> front(seconds.size(), true);
  for (std::size_t i = 0; i < seconds.size(); ++i)
    for (std::size_t j = 0; j < seconds.size() && front[i]; ++j)
      front[i] = !(seconds[j] <= seconds[i] && error[j] <= error[i] &&
                   (seconds[j] < seconds[i] || error[j] < error[i]));
  return front;
}

}  // namespace voxgi::reference
