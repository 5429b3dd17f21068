#pragma once
/// \file
/// A tiny deterministic PRNG and integer hashes. The standard library's distributions are
/// implementation-defined, so the data generator uses only these: the same seed gives the same
/// data on every platform and compiler.

#include <cstdint>

namespace tissue::datagen {

/// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// Hash of an integer lattice point and a seed, for lattice noise.
constexpr std::uint64_t hashLattice(std::int32_t x, std::int32_t y, std::int32_t z, std::uint64_t seed) {
  std::uint64_t h = mix64(seed + 0x9e3779b97f4a7c15ull);
  h = mix64(h ^ std::uint64_t(std::uint32_t(x)));
  h = mix64(h ^ (std::uint64_t(std::uint32_t(y)) << 21));
  return mix64(h ^ (std::uint64_t(std::uint32_t(z)) << 42));
}

/// Maps the top 53 bits of a hash to [0, 1).
constexpr double toUnit(std::uint64_t h) {
  return double(h >> 11) * 0x1.0p-53;
}

/// SplitMix64 generator: a 64-bit state advanced by the golden-ratio increment.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : m_state(seed) {}

  /// The next 64 random bits.
  std::uint64_t next() {
    m_state += 0x9e3779b97f4a7c15ull;
    return mix64(m_state);
  }
  /// Uniform in [0, 1).
  double uniform() { return toUnit(next()); }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t m_state;
};

}  // namespace tissue::datagen
