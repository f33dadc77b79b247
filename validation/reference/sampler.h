// The path tracer's samplers (docs/path-tracer.md, "Sampling"). Each gives a path's numbers as a
// function of (seed, pixel, sample index, dimension) only, so an image is bit-identical for any
// thread count and tile order. A path asks for them one (get1D) or two (get2D) at a time, in a
// fixed order: the pixel position, then per vertex the light pick and point, the lobe and
// direction, and Russian roulette.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>

#include <glm/vec2.hpp>

#include "common/counter_random.h"

namespace voxgi::reference {

enum class SamplerKind { sobol, independent };
// The names of the CLI, the study's sweeps and the benchmarks.
inline constexpr std::pair<const char*, SamplerKind> kSamplerNames[] = {
    {"sobol", SamplerKind::sobol}, {"independent", SamplerKind::independent}};

// x in [lo, hi) mapped onto [0, 1): the rest of a sample number that chose the interval, reused
// so that one 2D sample both makes a discrete choice and places a point (clamped below 1 against
// rounding, and 0 for an empty interval).
inline float stretch(float x, float lo, float hi) {
  if (!(hi > lo)) return 0.0f;
  return std::clamp((x - lo) / (hi - lo), 0.0f, 0x1.fffffep-1f);
}

// Independent uniform numbers: the d-th is a hash of (seed, pixel, sample, d). Plain Monte Carlo,
// whose error falls as 1/sqrt(N).
class IndependentSampler {
 public:
  IndependentSampler(uint64_t seed, uint64_t pixel, uint32_t sample)
      : rng_{mix64(seed ^ mix64(pixel ^ mix64(uint64_t(sample) + 0x632be59bd9b4e019ull)))} {}
  float get1D() { return rng_.next(); }
  glm::vec2 get2D() {
    const float u = rng_.next();
    return {u, rng_.next()};
  }

 private:
  CounterRandom rng_;
};

namespace sobol {

inline uint32_t reverseBits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// The first two dimensions of Sobol's sequence, a (0,2)-sequence in base 2: the van der Corput
// sequence, and the one whose direction numbers are v1 = 1/2, v(k+1) = v(k) xor v(k) / 2 (the
// primitive polynomial x + 1). Both are exact 32-bit fractions.
inline uint32_t dimension0(uint32_t i) {
  return reverseBits(i);
}
// Dimension 1 XORs the direction numbers of the index's set bits; a table per byte of the index
// does 8 bits at a time (a shuffled index has all 32 bits in play).
struct Dimension1Tables {
  uint32_t byte[4][256];
  constexpr Dimension1Tables() : byte{} {
    uint32_t v[32] = {};
    v[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    for (int b = 0; b < 4; ++b)
      for (uint32_t x = 0; x < 256; ++x) {
        uint32_t r = 0;
        for (int k = 0; k < 8; ++k)
          if (x >> k & 1u) r ^= v[8 * b + k];
        byte[b][x] = r;
      }
  }
};
inline constexpr Dimension1Tables kDimension1;

inline uint32_t dimension1(uint32_t i) {
  return kDimension1.byte[0][i & 255u] ^ kDimension1.byte[1][(i >> 8) & 255u] ^
         kDimension1.byte[2][(i >> 16) & 255u] ^ kDimension1.byte[3][i >> 24];
}

// A random nested uniform (Owen) scramble of the 32-bit fraction x [Burley 2020, §3]: each bit
// is flipped by a hash of the bits above it. The hash (Laine and Karras 2011's, with Burley's
// constants) lets bit j of its output depend on input bits 0..j only, so applied to the reversed
// bits it does that. It is a bijection that maps every aligned block of 2^m values (the same
// high bits) onto one: scrambled points keep the net property, and a scrambled index visits an
// aligned block of indices in another order.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
  x = reverseBits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverseBits(x);
}

// [0, 1) from the 24 high bits of a 32-bit fraction (exact as a float).
inline float toUnit(uint32_t x) {
  return float(x >> 8) * 0x1p-24f;
}

}  // namespace sobol

// Owen-scrambled Sobol' points, padded [Burley 2020]: each get2D is the (0,2)-sequence's point
// at the sample index, the index shuffled and both coordinates scrambled by hashes of (seed,
// pixel, which call); each get1D the van der Corput point likewise. So the first 2^m samples of a
// pixel are, per call, a (0,m,2)-net (every elementary interval of area 2^-m holds one point),
// and the calls and pixels are decorrelated by their scrambles.
class SobolSampler {
 public:
  SobolSampler(uint64_t seed, uint64_t pixel, uint32_t sample)
      : key_(mix64(seed ^ mix64(pixel + 0x2545f4914f6cdd1dull))), sample_(sample) {}
  float get1D() {
    const uint64_t h = next();
    const uint32_t i = sobol::owenScramble(sample_, uint32_t(h));
    return sobol::toUnit(sobol::owenScramble(sobol::dimension0(i), uint32_t(h >> 32)));
  }
  glm::vec2 get2D() {
    const uint64_t h = next(), g = mix64(h);
    const uint32_t i = sobol::owenScramble(sample_, uint32_t(h));
    return {sobol::toUnit(sobol::owenScramble(sobol::dimension0(i), uint32_t(h >> 32))),
            sobol::toUnit(sobol::owenScramble(sobol::dimension1(i), uint32_t(g)))};
  }

 private:
  // The hash of the next call: its index shuffle and scrambles.
  uint64_t next() { return mix64(key_ + 0x9e3779b97f4a7c15ull * ++call_); }

  uint64_t key_;
  uint32_t sample_;
  uint64_t call_ = 0;
};

}  // namespace voxgi::reference
