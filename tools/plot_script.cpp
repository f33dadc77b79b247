#include "tools/plot_script.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "common/io/output_file.h"

extern char** environ;

namespace voxgi::tools {

void runPlotScript(const char* script, const std::string& csv, const std::string& png,
                   const std::vector<std::string>& args) {
  const std::filesystem::path temp = std::filesystem::temp_directory_path();
  const std::string stem = "voxgi_plot_" + std::to_string(getpid());
  const std::filesystem::path scriptPath = temp / (stem + ".py"), drawn = temp / (stem + ".png");
  std::ofstream(scriptPath) << script;
  std::vector<std::string> command{"/usr/bin/python3", scriptPath.string(), csv, drawn.string()};
  command.insert(command.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : command) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  int status = -1;
  const int spawned = posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
  if (spawned == 0) waitpid(pid, &status, 0);
  std::filesystem::remove(scriptPath);
  if (spawned != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(drawn);
    throw std::runtime_error(
        "plotting with /usr/bin/python3 failed; it needs python3-matplotlib (scripts/setup "
        "installs it). The CSV is written: " +
        csv);
  }
  std::ifstream in(drawn, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(drawn);
  writeFileAtomically(png, bytes);
}

}  // namespace voxgi::tools
