// Runs the fuzz targets over files without libFuzzer: `voxgi_fuzz_replay TARGET DIR...` runs
// TARGET on every file under the folders (its seed corpus and regression inputs). Every build
// replays them as tests (tests/fuzz/CMakeLists.txt), the sanitizer builds included.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

#include "tests/fuzz/fuzz_target.h"

int main(int argc, char** argv) {
  using Target = int (*)(const uint8_t*, size_t);
  Target target = nullptr;
#define VOXGI_MATCH(name) \
  if (argc > 1 && std::strcmp(argv[1], #name) == 0) target = &voxgi::fuzz::name;
  VOXGI_FUZZ_TARGETS(VOXGI_MATCH)
#undef VOXGI_MATCH
  if (target == nullptr) {
    std::cerr << "usage: voxgi_fuzz_replay TARGET DIR... (a target of tests/fuzz)\n";
    return 2;
  }
  size_t files = 0;
  for (int a = 2; a < argc; ++a) {
    if (!std::filesystem::is_directory(argv[a])) continue;  // no regressions yet is fine
    for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[a])) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
      target(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++files;
    }
  }
  std::cout << "replayed " << files << " inputs through " << argv[1] << "\n";
  return files > 0 ? 0 : 1;
}
