// Running the voxgi binary from tests.
#pragma once

#include <string>

namespace voxgi::test {

struct CommandResult {
  int code;
  std::string output;  // stdout and stderr
};

// Runs `voxgi ARGS` through the shell, stdout and stderr together.
CommandResult voxgi(const std::string& args);
// The same with the process's CPU time limited to `cpuSeconds` (ulimit -t): a run that passes it
// is killed (code -1). CPU time, not wall time, so a loaded machine cannot make it fail.
CommandResult voxgiWithin(int cpuSeconds, const std::string& args);

}  // namespace voxgi::test
