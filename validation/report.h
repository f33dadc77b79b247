// Diff reports: JSON for tools, a table for people.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "validation/diff.h"

namespace voxgi::validation {

nlohmann::json toJson(const std::vector<StageReport>& reports);
void printReport(std::ostream& out, const std::vector<StageReport>& reports);

}  // namespace voxgi::validation
