// Checks that a large allocation will fit before it is made.
#pragma once

#include <cstdint>
#include <string>

namespace voxgi {

// Bytes the system can still hand out (MemAvailable from /proc/meminfo; 0 if unknown).
uint64_t availableMemoryBytes();

// Throws InputError(file, field, ...) when `bytes` exceeds the available memory, naming `what`.
void requireMemory(uint64_t bytes, const std::string& what, const std::string& file,
                   const std::string& field);

std::string formatBytes(uint64_t bytes);

}  // namespace voxgi
