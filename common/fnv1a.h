// FNV-1a, 64 bits, over bytes: a fingerprint for hashing and change detection, not a
// cryptographic hash.
#pragma once

#include <cstddef>
#include <cstdint>

namespace voxgi {

inline constexpr uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;

// Continues the hash `h` over `bytes` bytes at `data` (in memory order: little-endian words).
inline uint64_t fnv1a(const void* data, size_t bytes, uint64_t h = kFnv1aBasis) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  return h;
}

}  // namespace voxgi
