// The study's plots: a plotting script embedded in voxgi (tools/CMakeLists.txt) run by Debian's
// /usr/bin/python3, which has matplotlib (scripts/setup installs python3-matplotlib).
#pragma once

#include <string>
#include <vector>

namespace voxgi::tools {

// Writes `script` to a private temporary file and runs `/usr/bin/python3 SCRIPT CSV DRAWN ARGS...`;
// the PNG it draws at DRAWN (a private temporary) is then written to `png` like every other
// output. Throws std::runtime_error when the script fails, saying that the CSV is written.
void runPlotScript(const char* script, const std::string& csv, const std::string& png,
                   const std::vector<std::string>& args);

}  // namespace voxgi::tools
