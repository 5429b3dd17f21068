// The parallax study's error measure: on a flat plane the method's assumption (layers flat and
// parallel in tangent space; Oat 2006, Norberg 2010 §2.2) holds, so the texel it reads is the
// true one and both lie d tan(theta_t) from the shading point, theta_t by Snell's law.
#include "tissue/studies/parallax_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tissue::studies {
namespace {

double snellOffsetMm(double depthMm, double index, double angleDeg) {
  const double sinT = std::sin(angleDeg * std::numbers::pi / 180.0) / index;
  return depthMm * sinT / std::sqrt(1.0 - sinT * sinT);
}

TEST(ParallaxStudy, PlaneIsExactAndMatchesSnell) {
  const ParallaxSurface plane = parallaxPlane(40);
  for (const float index : {1.0f, 1.4f})
    for (const float angle : {0.0f, 30.0f, 60.0f, 75.0f}) {
      const ParallaxCell c = measureParallaxLookup(plane, 3.0f, index, angle, 400, 1e30f);
      ASSERT_GT(c.samples, 100) << angle;
      EXPECT_EQ(c.misses, 0) << angle;  // a plane never lets the refracted ray out
      EXPECT_EQ(c.reached, c.samples) << angle;
      EXPECT_LT(c.maxErrorMm, 1e-3) << "index " << index << " angle " << angle;
      const double expected = snellOffsetMm(3.0, index, angle);
      EXPECT_NEAR(c.meanTrueOffsetMm, expected, 1e-3 + 1e-4 * expected) << angle;
      EXPECT_NEAR(c.meanParallaxOffsetMm, expected, 1e-3 + 1e-4 * expected) << angle;
    }
}

TEST(ParallaxStudy, ClampLimitsTheLookupOffset) {
  // Eq. 17's clamp: at 85 degrees with n = 1 the offset d tan(85 deg) = 34 mm exceeds a 10 mm
  // transmission; the method then reads at most 10 mm away while the truth stays at 34 mm.
  const ParallaxCell c = measureParallaxLookup(parallaxPlane(40), 3.0f, 1.0f, 85.0f, 400, 10.0f);
  ASSERT_GT(c.reached, 100);
  EXPECT_LE(c.meanParallaxOffsetMm, 10.0 + 1e-3);
  EXPECT_NEAR(c.meanTrueOffsetMm, snellOffsetMm(3.0, 1.0, 85.0), 1e-2);
  EXPECT_NEAR(c.meanErrorMm, c.meanTrueOffsetMm - c.meanParallaxOffsetMm, 1e-2);
}

TEST(ParallaxStudy, SphereErrorGrowsWithViewAngle) {
  // A convex surface bends away from the flat-layer assumption: the true inner texel drifts from
  // the one the method reads more, the more obliquely the layer is seen.
  ParallaxStudyConfig config;
  config.depthsMm = {3.0f};
  config.refractiveIndices = {1.4f};
  config.viewAnglesDeg = {0.0f, 30.0f, 60.0f};
  config.samplePoints = 300;
  const auto rows = studyParallax({parallaxSphere(40.0, 60)}, config);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].cells.size(), 3u);
  EXPECT_EQ(rows[0].surface, "sphere_r40");
  const auto& c = rows[0].cells;
  for (const auto& cell : c)
    ASSERT_GT(cell.reached, 50);
  EXPECT_LT(c[0].meanErrorMm, c[1].meanErrorMm);
  EXPECT_LT(c[1].meanErrorMm, c[2].meanErrorMm);
}

}  // namespace
}  // namespace tissue::studies
