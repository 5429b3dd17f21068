#include "tissue/studies/deformations.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "tissue/core/vec_math.h"

namespace tissue::studies {

std::vector<std::uint32_t> applyPoke(std::span<const Float3> rest, std::span<const Float3> normals,
                                     std::uint32_t centerVertex, double fraction, float depthMm,
                                     std::span<Float3> out) {
  std::copy(rest.begin(), rest.end(), out.begin());
  const Float3 c = rest[centerVertex];
  std::vector<std::pair<float, std::uint32_t>> byDistance(rest.size());
  for (std::uint32_t i = 0; i < rest.size(); ++i) {
    const float dx = rest[i].x - c.x, dy = rest[i].y - c.y, dz = rest[i].z - c.z;
    byDistance[i] = {std::sqrt(dx * dx + dy * dy + dz * dz), i};
  }
  const std::size_t count =
      std::clamp<std::size_t>(std::size_t(std::llround(fraction * double(rest.size()))), 1, rest.size());
  std::nth_element(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(count - 1), byDistance.end());
  std::sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(count));
  // The radius is just beyond the farthest selected vertex, so every selected vertex moves.
  const float radius = byDistance[count - 1].first * 1.0001f + 1e-6f;
  std::vector<std::uint32_t> moved;
  moved.reserve(count);
  const Float3 n = normals[centerVertex];
  for (std::size_t k = 0; k < count; ++k) {
    const auto [d, i] = byDistance[k];
    const float w = 0.5f * (1.0f + std::cos(std::numbers::pi_v<float> * d / radius));
    out[i] = {rest[i].x - n.x * depthMm * w, rest[i].y - n.y * depthMm * w, rest[i].z - n.z * depthMm * w};
    moved.push_back(i);
  }
  std::sort(moved.begin(), moved.end());
  return moved;
}

void applyGlobalBend(std::span<const Float3> rest, float amplitudeMm, std::span<Float3> out) {
  const Bounds3 box = boundsOf(rest);
  const Float3 lo = box.lo, hi = box.hi;
  const float sx = std::max(hi.x - lo.x, 1e-6f), sy = std::max(hi.y - lo.y, 1e-6f);
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const float u = (rest[i].x - lo.x) / sx, v = (rest[i].y - lo.y) / sy;
    const float bend = amplitudeMm * 4.0f * u * (1.0f - u);
    const float ripple = 0.25f * amplitudeMm * std::sin(2.0f * std::numbers::pi_v<float> * (u + 0.5f * v));
    out[i] = {rest[i].x + 0.1f * ripple, rest[i].y, rest[i].z + bend + ripple};
  }
}

std::uint32_t topVertex(std::span<const Float3> positions) {
  return std::uint32_t(std::max_element(positions.begin(), positions.end(),
                                        [](const Float3& a, const Float3& b) { return a.z < b.z; }) -
                       positions.begin());
}

}  // namespace tissue::studies
