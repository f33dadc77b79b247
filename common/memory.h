// Checks that a large allocation will fit before it is made.
#pragma once

#include <cstdint>
#include <string>

namespace voxgi {

// Bytes this process can still allocate: the least of MemAvailable, what RLIMIT_AS and RLIMIT_DATA
// leave beside what it uses, and what its cgroup's memory.max leaves; kMemoryUnknown if none is
// known.
constexpr uint64_t kMemoryUnknown = ~uint64_t(0);
uint64_t availableMemoryBytes();

// Throws InputError(file, field, ...) when `bytes` exceeds the available memory, naming `what`.
void requireMemory(uint64_t bytes, const std::string& what, const std::string& file,
                   const std::string& field);

std::string formatBytes(uint64_t bytes);

}  // namespace voxgi
