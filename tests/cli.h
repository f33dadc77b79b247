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

}  // namespace voxgi::test
