#include "common/memory.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace voxgi {

uint64_t availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

std::string formatBytes(uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 5) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
  return text;
}

void requireMemory(uint64_t bytes, const std::string& what, const std::string& file,
                   const std::string& field) {
  const uint64_t available = availableMemoryBytes();
  if (available != 0 && bytes > available)
    throw InputError(file, field,
                     what + " needs " + formatBytes(bytes) + " but only " + formatBytes(available) +
                         " is available");
}

}  // namespace voxgi
