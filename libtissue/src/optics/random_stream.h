#pragma once
// Private: the random streams of the Monte Carlo batches. xoshiro256** (Blackman & Vigna 2018,
// "Scrambled linear pseudorandom number generators"), its state filled by splitmix64 from
// (seed, stream) so that every batch has its own reproducible stream.

#include <cstdint>

namespace tissue::optics::detail {

/// One random stream; uniform() gives doubles in (0, 1], safe for -log(xi).
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t x = seed ^ (stream * 0xD1B54A32D192ED03ull);
    for (auto& s : m_s)
      s = splitMix64(x);
  }

  /// Uniform in (0, 1], 53 random bits.
  double uniform() { return static_cast<double>((next() >> 11) + 1) * 0x1.0p-53; }

  /// A uniform azimuth phi as (cos phi, sin phi) without trigonometry: a point (u, v) uniform in
  /// the unit disc by rejection (4 / pi pairs on average) gives cos phi = (u^2 - v^2) / s and
  /// sin phi = 2 u v / s with s = u^2 + v^2 (von Neumann 1951; the angle doubles, so the map is
  /// uniform on the circle). sincos was 30% of the 1D Monte Carlo's time.
  void azimuth(double& cosPhi, double& sinPhi) {
    double u = 0.0, v = 0.0, s = 0.0;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s > 1.0 || s < 1e-300);
    cosPhi = (u * u - v * v) / s;
    sinPhi = 2.0 * u * v / s;
  }

 private:
  static std::uint64_t splitMix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  static std::uint64_t rotl(std::uint64_t v, int k) { return (v << k) | (v >> (64 - k)); }
  std::uint64_t next() {
    const std::uint64_t result = rotl(m_s[1] * 5, 7) * 9;
    const std::uint64_t t = m_s[1] << 17;
    m_s[2] ^= m_s[0];
    m_s[3] ^= m_s[1];
    m_s[1] ^= m_s[2];
    m_s[0] ^= m_s[3];
    m_s[2] ^= t;
    m_s[3] = rotl(m_s[3], 45);
    return result;
  }
  std::uint64_t m_s[4];
};

}  // namespace tissue::optics::detail
