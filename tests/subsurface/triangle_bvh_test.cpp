// The reference's BVH against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::subsurface {
namespace {

// A UV sphere of radius r, outward-facing triangles.
void uvSphere(double r, int rings, int segments, std::vector<Float3>& p, std::vector<Triangle>& t) {
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
      p.push_back({float(r * std::sin(th) * std::cos(ph)), float(r * std::sin(th) * std::sin(ph)),
                   float(r * std::cos(th))});
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = i * segments + j, b = i * segments + (j + 1) % segments;
      const std::uint32_t c = a + segments, d = b + segments;
      if (i > 0) t.push_back({a, c, b});
      if (i + 1 < rings) t.push_back({b, c, d});
    }
}

TEST(TriangleBvh, NearestHitEqualsBruteForce) {
  std::vector<Float3> p;
  std::vector<Triangle> t;
  uvSphere(10.0, 24, 48, p, t);
  const TriangleBvh bvh(p, t);
  std::vector<Triangle> one(1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int k = 0; k < 150; ++k) {
    std::array<double, 3> o = {u(rng) * 15, u(rng) * 15, u(rng) * 15}, d = {u(rng), u(rng), u(rng)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d)
      x /= len;
    double best = 1e30;
    for (const Triangle& tri : t) {
      one[0] = tri;
      const TriangleBvh single(p, one);
      if (const auto h = single.intersect(o, d, 1e-9, 1e9)) best = std::min(best, h->t);
    }
    const auto h = bvh.intersect(o, d, 1e-9, 1e9);
    ASSERT_EQ(h.has_value(), best < 1e30) << k;
    if (h) {
      EXPECT_NEAR(h->t, best, 1e-9);
      ++hits;
    }
  }
  EXPECT_GT(hits, 30);
}

TEST(TriangleBvh, RaysFromTheCentreHitTheSphereAtItsRadiusFromInside) {
  std::vector<Float3> p;
  std::vector<Triangle> t;
  uvSphere(10.0, 32, 64, p, t);
  const TriangleBvh bvh(p, t);
  std::mt19937 rng(1);
  std::normal_distribution<double> n;
  for (int k = 0; k < 200; ++k) {
    std::array<double, 3> d = {n(rng), n(rng), n(rng)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d)
      x /= len;
    const auto h = bvh.intersect({0, 0, 0}, d, 1e-9, 1e9);
    ASSERT_TRUE(h.has_value());
    EXPECT_GT(h->t, 9.9);  // inscribed polyhedron: the chord sagitta is below 0.1 mm
    EXPECT_LE(h->t, 10.0 + 1e-6);
    const auto nrm = bvh.faceNormal(h->triangle);
    EXPECT_GT(nrm[0] * d[0] + nrm[1] * d[1] + nrm[2] * d[2], 0.9) << "outward normals";
  }
}

}  // namespace
}  // namespace tissue::subsurface
