#include "closed_surfaces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "tissue/sim/vec3.h"

namespace tissue::sim::test {

ClosedSurface boxSurface(Float3 lo, Float3 hi) {
  ClosedSurface s;
  for (int c = 0; c < 8; ++c)
    s.positions.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
  // Each side as a quad (counter-clockwise from outside), split in two.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

ClosedSurface icosphere(double radius, Float3 centre, int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3d> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(0.5 * (v[a] + v[b]));
      return mid[key] = static_cast<std::uint32_t>(v.size() - 1);
    };
    std::vector<Triangle> next;
    for (const Triangle& tri : f) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                          ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  ClosedSurface out;
  for (const Vec3d& p : v) {
    const Vec3d q = (radius / length(p)) * p;
    out.positions.push_back({static_cast<float>(q.x + double{centre.x}),
                             static_cast<float>(q.y + double{centre.y}),
                             static_cast<float>(q.z + double{centre.z})});
  }
  out.triangles = std::move(f);
  return out;
}

double enclosedVolume(const std::vector<Float3>& positions, const std::vector<Triangle>& triangles) {
  double sum = 0.0;
  for (const Triangle& t : triangles) {
    const Vec3d a{positions[t[0]].x, positions[t[0]].y, positions[t[0]].z};
    const Vec3d b{positions[t[1]].x, positions[t[1]].y, positions[t[1]].z};
    const Vec3d c{positions[t[2]].x, positions[t[2]].y, positions[t[2]].z};
    sum += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  }
  return sum / 6.0;
}

}  // namespace tissue::sim::test
