#include "tests/cli.h"

#include <array>
#include <cstdio>
#include <sys/wait.h>

namespace voxgi::test {

namespace {

CommandResult run(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (pipe && fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace

CommandResult voxgi(const std::string& args) {
  return run(std::string(VOXGI_BINARY) + " " + args + " 2>&1");
}

CommandResult voxgiWithin(int cpuSeconds, const std::string& args) {
  return run("(ulimit -t " + std::to_string(cpuSeconds) + "; exec " + VOXGI_BINARY + " " + args +
             ") 2>&1");
}

}  // namespace voxgi::test
