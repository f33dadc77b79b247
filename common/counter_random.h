// Counter-based random numbers: every number is a hash of (seed, what it is for, its index), so a
// result never depends on which thread drew it or in what order (docs/path-tracer.md).
#pragma once

#include <cstdint>

namespace voxgi {

// The splitmix64 finaliser.
inline uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// The numbers of one key: the d-th is the d-th output of SplitMix64 seeded with the key.
struct CounterRandom {
  uint64_t key;
  uint64_t dimension = 0;
  // Uniform in [0, 1), 24 bits.
  float next() { return float(mix64(key + 0x9e3779b97f4a7c15ull * ++dimension) >> 40) * 0x1p-24f; }
  // Uniform in [0, 1), 53 bits.
  double nextDouble() {
    return double(mix64(key + 0x9e3779b97f4a7c15ull * ++dimension) >> 11) * 0x1p-53;
  }
};

}  // namespace voxgi
