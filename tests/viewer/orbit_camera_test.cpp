// The orbit camera: its home view is frameBoundingBox's, orbits are rotations about the target,
// pitch and zoom stay within their limits.
#include "orbit_camera.h"

#include <gtest/gtest.h>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

constexpr Float3 kLo{-90.0f, -56.0f, -31.0f}, kHi{90.0f, 56.0f, 51.0f};  // mm, the liver's box

void expectNear(Float3 actual, Float3 expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(OrbitCameraTest, HomeViewFramesTheBox) {
  const OrbitCamera orbit(kLo, kHi, 1.6f);
  const render::Camera expected = render::frameBoundingBox(kLo, kHi, 1.6f);
  const render::Camera camera = orbit.camera();
  expectNear(camera.eye, expected.eye, 1e-3f);
  expectNear(camera.target, expected.target, 1e-4f);
  EXPECT_LT(camera.nearMm, length(camera.eye - camera.target) - 0.5f * length(kHi - kLo));
  EXPECT_GT(camera.farMm, length(camera.eye - camera.target) + 0.5f * length(kHi - kLo));
}

TEST(OrbitCameraTest, OrbitKeepsTheDistanceAndAFullTurnComesBack) {
  OrbitCamera orbit(kLo, kHi, 1.6f);
  const render::Camera home = orbit.camera();
  const float turnPixels = 360.0f / OrbitSettings{}.degreesPerPixel;
  orbit.orbit(turnPixels / 4, 0.0);
  const render::Camera quarter = orbit.camera();
  EXPECT_NEAR(length(quarter.eye - quarter.target), length(home.eye - home.target), 1e-3f);
  EXPECT_GT(length(quarter.eye - home.eye), 10.0f);
  orbit.orbit(3 * turnPixels / 4, 0.0);
  expectNear(orbit.camera().eye, home.eye, 1e-2f);
}

TEST(OrbitCameraTest, PitchStopsShortOfThePoles) {
  OrbitCamera orbit(kLo, kHi, 1.6f);
  orbit.orbit(0.0, 1e6);
  const render::Camera camera = orbit.camera();
  const Float3 forward = normalize(camera.target - camera.eye);
  EXPECT_GT(forward.y, -1.0f + 1e-4f);
  EXPECT_LT(forward.y, -0.99f);
}

TEST(OrbitCameraTest, ZoomIsClampedAndReversible) {
  OrbitCamera orbit(kLo, kHi, 1.6f);
  const float home = orbit.distanceMm();
  orbit.zoom(3.0);
  EXPECT_NEAR(orbit.distanceMm(), home * 0.9f * 0.9f * 0.9f, 1e-3f);
  orbit.zoom(-3.0);
  EXPECT_NEAR(orbit.distanceMm(), home, 1e-3f);
  orbit.zoom(1000.0);
  EXPECT_GT(orbit.distanceMm(), 0.0f);
  EXPECT_GT(orbit.camera().nearMm, 0.0f);
  orbit.reset();
  EXPECT_FLOAT_EQ(orbit.distanceMm(), home);
}

}  // namespace
}  // namespace tissue::viewer
