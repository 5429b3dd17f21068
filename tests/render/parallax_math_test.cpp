// Layered-parallax arithmetic (Norberg 2010 eq. 15-18 with Snell's law) against the analytic
// refraction of a view ray at a flat interface, and the Poisson disc of the lightmap blur.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tissue/render/parallax_math.h"

namespace tissue::render {
namespace {

constexpr float kDeg = std::numbers::pi_v<float> / 180.0f;
const Float3 kUp{0.0f, 0.0f, 1.0f};

// A unit view vector (toward the eye) at `angleDeg` from the normal, azimuth `azimuthDeg`.
Float3 view(float angleDeg, float azimuthDeg = 0.0f) {
  const float a = angleDeg * kDeg, b = azimuthDeg * kDeg;
  return {std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), std::cos(a)};
}

float length(Float2 v) {
  return std::sqrt(v.x * v.x + v.y * v.y);
}

TEST(ParallaxMath, NormalIncidenceHasNoOffset) {
  for (const float n : {1.0f, 1.33f, 1.4f}) {
    const TransmissionLookup t = transmissionLookup(kUp, kUp, n, 2.0f);
    EXPECT_NEAR(length(t.offsetMm), 0.0f, 1e-6f);
    EXPECT_NEAR(t.transmissionMm, 2.0f, 1e-6f);  // eq. 17: s = d / |T_z| = d
    EXPECT_NEAR(t.direction.z, -1.0f, 1e-6f);
  }
}

TEST(ParallaxMath, OffsetIsDepthTimesTanOfTheSnellRefractedAngle) {
  const float depth = 3.0f;
  for (const float n : {1.0f, 1.33f, 1.4f}) {
    for (const float angle : {10.0f, 30.0f, 45.0f, 60.0f, 75.0f, 85.0f}) {
      const float thetaT = std::asin(std::sin(angle * kDeg) / n);  // Snell
      const TransmissionLookup t = transmissionLookup(view(angle, 40.0f), kUp, n, depth);
      EXPECT_NEAR(length(t.offsetMm), depth * std::tan(thetaT), 1e-4f * depth / std::cos(thetaT))
          << "n " << n << ", " << angle << " deg";
      EXPECT_NEAR(t.transmissionMm, depth / std::cos(thetaT), 1e-5f * depth / std::cos(thetaT) + 1e-5f)
          << n << " " << angle;
      // The offset points away from the eye, along the view's azimuth.
      EXPECT_LT(t.offsetMm.x * std::cos(40.0f * kDeg) + t.offsetMm.y * std::sin(40.0f * kDeg), 0.0f);
      const Float3 d = t.direction;
      EXPECT_NEAR(d.x * d.x + d.y * d.y + d.z * d.z, 1.0f, 1e-5f);
    }
  }
}

TEST(ParallaxMath, IndexOneContinuesTheViewRayStraight) {
  // Eq. 15-16 with the geometric normal: T = -V.
  for (const float angle : {0.0f, 20.0f, 50.0f, 80.0f}) {
    const Float3 v = view(angle, 120.0f);
    const TransmissionLookup t = transmissionLookup(v, kUp, 1.0f, 1.0f);
    EXPECT_NEAR(t.direction.x, -v.x, 1e-6f);
    EXPECT_NEAR(t.direction.y, -v.y, 1e-6f);
    EXPECT_NEAR(t.direction.z, -v.z, 1e-6f);
  }
}

TEST(ParallaxMath, AMappedNormalTiltsTheTransmissionVectorLikeEquations15And16) {
  // Seen from straight above, a normal tilted by a toward +x reflects -V to 2a from -z; eq. 16
  // mirrors it below the plane: T leans 2a toward +x (Norberg §4.2's refraction by the map).
  const float a = 10.0f * kDeg;
  const Float3 n{std::sin(a), 0.0f, std::cos(a)};
  const TransmissionLookup t = transmissionLookup(kUp, n, 1.0f, 2.0f);
  EXPECT_NEAR(t.direction.x, std::sin(2.0f * a), 1e-5f);
  EXPECT_NEAR(t.offsetMm.x, 2.0f * std::tan(2.0f * a), 1e-4f);
}

TEST(ParallaxMath, GrazingTransmissionIsClamped) {
  const TransmissionLookup t = transmissionLookup(view(89.9f), kUp, 1.0f, 2.0f, 20.0f);
  EXPECT_FLOAT_EQ(t.transmissionMm, 20.0f);
  EXPECT_LE(length(t.offsetMm), 20.0f);
}

TEST(ParallaxMath, PoissonDiscIsInsideSpacedAndCentred) {
  for (const int count : {8, 16, 32}) {
    const auto disc = poissonDisc(count);
    ASSERT_EQ(disc.size(), static_cast<std::size_t>(count));
    Float2 mean{};
    float closest = 10.0f;
    for (std::size_t i = 0; i < disc.size(); ++i) {
      EXPECT_LE(length(disc[i]), 1.0f + 1e-6f);
      mean.x += disc[i].x, mean.y += disc[i].y;
      for (std::size_t j = i + 1; j < disc.size(); ++j)
        closest = std::min(closest, length({disc[i].x - disc[j].x, disc[i].y - disc[j].y}));
    }
    EXPECT_NEAR(mean.x, 0.0f, 1e-5f);  // a blur by the disc does not shift the map
    EXPECT_NEAR(mean.y, 0.0f, 1e-5f);
    // Best-candidate sampling keeps points apart: well above what uniform random points reach
    // (for N points in the unit disc, packing allows about 1.9 / sqrt(N)).
    EXPECT_GT(closest, 0.6f / std::sqrt(static_cast<float>(count))) << count;
  }
  EXPECT_EQ(poissonDisc(16, 3), poissonDisc(16, 3));  // deterministic
}

TEST(ParallaxMath, MultipassRadiusKeepsTheTotalVariance) {
  // A uniform disc of radius r has variance r^2 / 4 per axis; n passes add variances.
  const float total = 6.0f;
  for (const int n : {1, 2, 3, 4}) {
    const float r = poissonPassRadiusMm(total, n);
    EXPECT_NEAR(n * r * r / 4.0f, total * total / 4.0f, 1e-4f);
  }
  EXPECT_EQ(poissonPassRadiusMm(total, 0), 0.0f);
}

}  // namespace
}  // namespace tissue::render
