// Layered parallax arithmetic: Norberg 2010 eq. 15-18 with Snell's law, and the Poisson disc.
#include "tissue/render/parallax_math.h"

#include <algorithm>
#include <cmath>

namespace tissue::render {

TransmissionLookup transmissionLookup(Float3 v, Float3 n, float relativeIndex, float depthMm,
                                      float maxTransmissionMm) {
  // Eq. 15: R = -V - 2 (-V . N) N, the view ray reflected about the (mapped) normal.
  const float vn = -(v.x * n.x + v.y * n.y + v.z * n.z);
  const Float3 r{-v.x - 2.0f * vn * n.x, -v.y - 2.0f * vn * n.y, -v.z - 2.0f * vn * n.z};
  // Eq. 16: T = (R_x, R_y, -R_z), mirrored below the tangent plane. With the geometric normal
  // this is -V: the ray goes on straight. Snell: the tangential part shrinks by 1 / n.
  const float eta = std::max(relativeIndex, 1.0f);
  const Float2 tangential{r.x / eta, r.y / eta};
  const float sin2 = std::min(tangential.x * tangential.x + tangential.y * tangential.y, 1.0f);
  // A view below the mapped normal's horizon (silhouettes) keeps a tiny downward component.
  const float tz = -std::max(std::sqrt(1.0f - sin2), 1e-4f);
  TransmissionLookup out;
  out.direction = {tangential.x, tangential.y, tz};
  // Eq. 17: s = d / |T_z|; eq. 18: the offset s (T_x, T_y).
  out.transmissionMm = std::min(depthMm / std::abs(tz), maxTransmissionMm);
  out.offsetMm = {out.transmissionMm * tangential.x, out.transmissionMm * tangential.y};
  return out;
}

std::vector<Float2> poissonDisc(int count, std::uint32_t seed) {
  const int pairs = std::clamp(count, 2, 64) / 2;
  std::uint32_t state = seed * 747796405u + 2891336453u;
  auto uniform = [&state] {  // PCG-style LCG step, top 24 bits
    state = state * 747796405u + 2891336453u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  std::vector<Float2> points;
  for (int i = 0; i < pairs; ++i) {
    Float2 best{};
    float bestDistance = -1.0f;
    for (int c = 0; c < 8 * (i + 1); ++c) {  // Mitchell: more candidates as the disc fills
      const float radius = std::sqrt(uniform()), angle = 6.28318531f * uniform();
      const Float2 p{radius * std::cos(angle), radius * std::sin(angle)};
      float nearest = 4.0f;
      for (const Float2& q : points)
        nearest = std::min(nearest, (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y));
      nearest = std::min(nearest, 4.0f * (p.x * p.x + p.y * p.y));  // its own mirror -p
      if (nearest > bestDistance) bestDistance = nearest, best = p;
    }
    points.push_back(best);
    points.push_back({-best.x, -best.y});
  }
  return points;
}

float poissonPassRadiusMm(float totalRadiusMm, int passes) {
  return passes > 0 ? totalRadiusMm / std::sqrt(static_cast<float>(passes)) : 0.0f;
}

}  // namespace tissue::render
