#include "tests/fuzz/fuzz_target.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace voxgi::fuzz {

const std::string& workFolder() {
  static const std::string dir = [] {
    const auto d =
        std::filesystem::temp_directory_path() / ("voxgi_fuzz_" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

std::string writeInput(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = workFolder() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace voxgi::fuzz
