#include "common/memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace voxgi {
namespace {

// The value of `key` (in kB) in a /proc file like meminfo or self/status, in bytes.
uint64_t procKiB(const char* file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) {
      std::istringstream fields(line.substr(key.size()));
      uint64_t kib = 0;
      if (fields >> kib) return kib * 1024;
    }
  return kMemoryUnknown;
}

// What a resource limit still allows, given what the process uses of it now.
uint64_t underLimit(int resource, uint64_t used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || used == kMemoryUnknown)
    return kMemoryUnknown;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

// What the cgroup (v2) of the process may still charge: memory.max - memory.current.
uint64_t underCgroup() {
  std::ifstream self("/proc/self/cgroup");
  std::string line, group;
  while (std::getline(self, line))
    if (line.rfind("0::", 0) == 0) group = line.substr(3);
  if (group.empty()) return kMemoryUnknown;
  const std::string dir = "/sys/fs/cgroup" + group;
  std::ifstream maxFile(dir + "/memory.max"), currentFile(dir + "/memory.current");
  uint64_t max = 0, current = 0;
  if (!(maxFile >> max) || !(currentFile >> current)) return kMemoryUnknown;  // "max": no limit
  return max > current ? max - current : 0;
}

}  // namespace

uint64_t availableMemoryBytes() {
  // The least of what the system has free and what this process may still take: an
  // address-space or data limit (ulimit -v / -d) or a container's cgroup limit fails an
  // allocation long before MemAvailable runs out.
  uint64_t available = procKiB("/proc/meminfo", "MemAvailable:");
  available = std::min(available, underLimit(RLIMIT_AS, procKiB("/proc/self/status", "VmSize:")));
  available = std::min(available, underLimit(RLIMIT_DATA, procKiB("/proc/self/status", "VmData:")));
  available = std::min(available, underCgroup());
  return available;
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
  if (available != kMemoryUnknown && bytes > available)
    throw InputError(file, field,
                     what + " needs " + formatBytes(bytes) + " but only " + formatBytes(available) +
                         " is available");
}

}  // namespace voxgi
