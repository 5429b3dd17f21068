// Picking: Möller-Trumbore against analytic points, misses, nearest of several hits, and the
// cursor ray against its inverse projection.
#include "ray_pick.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

constexpr Float3 kA{0.0f, 0.0f, 0.0f}, kB{10.0f, 0.0f, 0.0f}, kC{0.0f, 10.0f, 0.0f};  // mm, in z = 0

void expectNear(Float3 actual, Float3 expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(RayPickTest, PerpendicularRayHitsAtItsFootPoint) {
  const Ray ray{{2.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}};
  const auto t = intersectTriangle(ray, kA, kB, kC);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 5.0f, 1e-5f);
}

TEST(RayPickTest, ObliqueRayHitsAtTheAnalyticPoint) {
  // From (0, 0, 10) along (1, 1, -5)/sqrt(27): z = 0 at t = 2 sqrt(27), the point (2, 2, 0).
  const Ray ray{{0.0f, 0.0f, 10.0f}, normalize({1.0f, 1.0f, -5.0f})};
  const auto hit = nearestHit(ray, std::vector<Float3>{kA, kB, kC}, std::vector<Triangle>{{0, 1, 2}});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->triangle, 0u);
  EXPECT_NEAR(hit->distanceMm, 2.0f * std::sqrt(27.0f), 1e-4f);
  expectNear(hit->pointMm, {2.0f, 2.0f, 0.0f}, 1e-4f);
}

TEST(RayPickTest, BackFacesAreHitToo) {
  const Ray ray{{2.0f, 3.0f, -5.0f}, {0.0f, 0.0f, 1.0f}};
  const auto t = intersectTriangle(ray, kA, kB, kC);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 5.0f, 1e-5f);
}

TEST(RayPickTest, MissesMiss) {
  // Beside the hypotenuse, behind the origin, parallel to the plane, and pointing away.
  EXPECT_FALSE(intersectTriangle({{6.0f, 6.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, kA, kB, kC));
  EXPECT_FALSE(intersectTriangle({{-1.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, kA, kB, kC));
  EXPECT_FALSE(intersectTriangle({{2.0f, 3.0f, -5.0f}, {0.0f, 0.0f, -1.0f}}, kA, kB, kC));
  EXPECT_FALSE(intersectTriangle({{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, kA, kB, kC));
  EXPECT_FALSE(intersectTriangle({{2.0f, 3.0f, 5.0f}, {0.0f, 0.0f, 1.0f}}, kA, kB, kC));
  EXPECT_FALSE(nearestHit({{20.0f, 20.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, std::vector<Float3>{kA, kB, kC},
                          std::vector<Triangle>{{0, 1, 2}}));
}

TEST(RayPickTest, NearestOfTwoHitsWinsWhateverTheOrder) {
  // Two parallel triangles, the far one (z = -4) listed first.
  const std::vector<Float3> positions{{0, 0, -4}, {10, 0, -4}, {0, 10, -4}, kA, kB, kC};
  const std::vector<Triangle> triangles{{0, 1, 2}, {3, 4, 5}};
  const auto hit = nearestHit({{2.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, positions, triangles);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->triangle, 1u);
  EXPECT_NEAR(hit->distanceMm, 5.0f, 1e-5f);
  const auto fromBelow = nearestHit({{2.0f, 3.0f, -9.0f}, {0.0f, 0.0f, 1.0f}}, positions, triangles);
  ASSERT_TRUE(fromBelow);
  EXPECT_EQ(fromBelow->triangle, 0u);
  EXPECT_NEAR(fromBelow->distanceMm, 5.0f, 1e-5f);
}

TEST(RayPickTest, CursorRayGoesThroughTheProjectedPoint) {
  render::Camera camera;
  camera.eye = {30.0f, 40.0f, 150.0f};
  camera.target = {5.0f, -10.0f, 0.0f};
  const int width = 800, height = 500;
  for (const Float3 point : {Float3{0, 0, 0}, Float3{20, -15, 10}, Float3{-25, 30, -20}}) {
    const auto cursor = projectToCursor(camera, point, width, height);
    ASSERT_TRUE(cursor);
    const Ray ray = rayFromCursor(camera, cursor->x, cursor->y, width, height);
    const Float3 toPoint = point - ray.origin;
    const float offRay = length(toPoint - ray.direction * dot(toPoint, ray.direction));
    EXPECT_LT(offRay, 1e-3f) << "mm from the ray";
  }
}

TEST(RayPickTest, CursorRaysSpanTheFieldOfView) {
  render::Camera camera;  // looks down -z, 40 degrees vertically
  const int width = 800, height = 400;
  const Ray centre = rayFromCursor(camera, width / 2.0, height / 2.0, width, height);
  expectNear(centre.direction, {0.0f, 0.0f, -1.0f}, 1e-6f);
  const Ray top = rayFromCursor(camera, width / 2.0, 0.0, width, height);
  EXPECT_NEAR(std::atan2(top.direction.y, -top.direction.z), 20.0f * std::numbers::pi_v<float> / 180.0f,
              1e-5f);
  const Ray left = rayFromCursor(camera, 0.0, height / 2.0, width, height);
  const float halfHorizontal = std::atan(std::tan(20.0f * std::numbers::pi_v<float> / 180.0f) * 2.0f);
  EXPECT_NEAR(std::atan2(-left.direction.x, -left.direction.z), halfHorizontal, 1e-5f);
  EXPECT_FALSE(projectToCursor(camera, {0.0f, 0.0f, 300.0f}, width, height)) << "behind the eye";
}

}  // namespace
}  // namespace tissue::viewer
