// The layered-parallax error study (Oat 2006; Norberg 2010 §2.2): the method's lookup against
// the refracted ray meeting the true inner layer.
#include "tissue/studies/parallax_study.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "tissue/render/parallax_math.h"
#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::studies {
namespace {

using Vec = std::array<double, 3>;

Vec vec(Float3 a) {
  return {double(a.x), double(a.y), double(a.z)};
}
Vec add(Vec a, Vec b, double s = 1.0) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
double dot(Vec a, Vec b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(Vec a, Vec b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec unit(Vec a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
// x T + y B + z N: from the tangent frame to world.
Vec frame(Vec T, Vec B, Vec N, double x, double y, double z) {
  return {x * T[0] + y * B[0] + z * N[0], x * T[1] + y * B[1] + z * N[1], x * T[2] + y * B[2] + z * N[2]};
}
double distance(Vec a, Vec b) {
  const Vec d = add(a, b, -1.0);
  return std::sqrt(dot(d, d));
}

ParallaxSurface gridSurface(bool sphere, double radius, int n) {
  ParallaxSurface s;
  s.name = sphere ? "sphere_r" + std::to_string(int(std::lround(radius))) : "plane";
  s.what = sphere ? "sphere, radius " + std::to_string(int(std::lround(radius))) + " mm"
                  : "flat plane (control: the method's assumption holds)";
  s.sampleBoxMm = sphere ? Vec{0.0, 0.0, 0.95 * radius} : Vec{100.0, 100.0, 0.0};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n, v = double(j) / n;
      if (sphere) {
        const double phi = 2.0 * std::numbers::pi * u, theta = std::numbers::pi * v;
        const Vec nrm{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
        s.positions.push_back({float(radius * nrm[0]), float(radius * nrm[1]), float(radius * nrm[2])});
        s.normals.push_back({float(nrm[0]), float(nrm[1]), float(nrm[2])});
      } else {
        s.positions.push_back({float(300.0 * (u - 0.5)), float(300.0 * (v - 0.5)), 0.0f});
        s.normals.push_back({0.0f, 0.0f, 1.0f});
      }
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
      // Counter-clockwise seen from outside (+z for the plane, outward for the sphere).
      if (sphere) {
        s.triangles.push_back({a, c, b});
        s.triangles.push_back({b, c, d});
      } else {
        s.triangles.push_back({a, b, d});
        s.triangles.push_back({a, d, c});
      }
    }
  return s;
}

// Splitmix-style hash to [0, 1): a fixed azimuth per sample point.
double hash01(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return double((x ^ (x >> 31)) >> 11) / 9007199254740992.0;
}

subsurface::TriangleBvh innerBvh(const ParallaxSurface& s, float depth) {
  std::vector<Float3> pushed(s.positions.size());
  for (std::size_t i = 0; i < pushed.size(); ++i)
    pushed[i] = {s.positions[i].x - depth * s.normals[i].x, s.positions[i].y - depth * s.normals[i].y,
                 s.positions[i].z - depth * s.normals[i].z};
  return subsurface::TriangleBvh(pushed, s.triangles);
}

ParallaxCell measure(const ParallaxSurface& s, const subsurface::TriangleBvh& outer,
                     const subsurface::TriangleBvh& inner, float depthMm, float index, float angleDeg,
                     int points, float maxTransmission) {
  std::vector<double> errors;  // mm, rays that reach the layer
  double parallaxOffset = 0.0, trueOffset = 0.0;
  ParallaxCell cell;
  cell.viewAngleDeg = angleDeg;
  const std::size_t stride = std::max<std::size_t>(1, s.triangles.size() / std::size_t(std::max(points, 1)));
  const double a = double(angleDeg) * std::numbers::pi / 180.0;
  for (std::size_t v = 0; v < s.triangles.size(); v += stride) {
    // A point inside the triangle (never a vertex, where rays graze the mesh's edges), with the
    // interpolated normal.
    const Triangle& tri = s.triangles[v];
    double b1 = hash01(3 * v + 1), b2 = hash01(3 * v + 2);
    if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
    b1 = 0.05 + 0.9 * b1, b2 = 0.05 + 0.9 * b2;
    const double b0 = std::max(1.0 - b1 - b2, 0.0);
    auto mix = [&](const std::vector<Float3>& f) {
      return add(add(Vec{b0 * double(f[tri[0]].x), b0 * double(f[tri[0]].y), b0 * double(f[tri[0]].z)},
                     vec(f[tri[1]]), b1),
                 vec(f[tri[2]]), b2);
    };
    const Vec P = mix(s.positions), N = unit(mix(s.normals));
    bool outside = false;
    for (int k = 0; k < 3; ++k)
      outside = outside || (s.sampleBoxMm[k] > 0.0 && std::abs(P[k]) > s.sampleBoxMm[k]);
    if (outside) continue;
    const Vec T = unit(cross(std::abs(N[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0}, N)), B = cross(N, T);
    const double phi = 2.0 * std::numbers::pi * hash01(3 * v);
    const Float3 viewTangent{float(std::sin(a) * std::cos(phi)), float(std::sin(a) * std::sin(phi)),
                             float(std::cos(a))};
    // The method: eq. 15-18 with the geometric normal, the offset in the tangent plane.
    const auto lookup = render::transmissionLookup(viewTangent, {0, 0, 1}, index, depthMm, maxTransmission);
    const Vec offset = frame(T, B, N, double(lookup.offsetMm.x), double(lookup.offsetMm.y), 0.0);
    // ... read through the UV Jacobian at P: the surface point under P + offset (along -N).
    const double h = std::sqrt(dot(offset, offset)) + 1.0;
    const auto down = outer.intersect(add(add(P, offset), N, h), {-N[0], -N[1], -N[2]}, 0.0, 3.0 * h);
    // The truth: the refracted ray to the inner surface (the outer one moved by -d N), unless it
    // leaves the outer surface first.
    const Vec t = unit(
        frame(T, B, N, double(lookup.direction.x), double(lookup.direction.y), double(lookup.direction.z)));
    const auto hit = inner.intersect(P, t, 0.0, 1e4);
    ++cell.samples;
    if (!down) continue;  // the lookup falls off an open border: not a sample
    const bool exits = !hit || outer.intersect(P, t, 1e-3, hit->t).has_value();
    if (exits) {
      ++cell.misses;
      continue;
    }
    // The inner surface shares the outer one's triangles: the hit's barycentrics on the outer
    // triangle are the texel the true inner layer shows.
    auto at = [&](const subsurface::RayHit& r) {
      const Triangle& hitTriangle = s.triangles[r.triangle];
      const Vec p0 = vec(s.positions[hitTriangle[0]]);
      const double w0 = 1.0 - r.b1 - r.b2;
      return add(add(Vec{p0[0] * w0, p0[1] * w0, p0[2] * w0}, vec(s.positions[hitTriangle[1]]), r.b1),
                 vec(s.positions[hitTriangle[2]]), r.b2);
    };
    const Vec truth = at(*hit), method = at(*down);
    errors.push_back(distance(truth, method));
    parallaxOffset += distance(method, P);
    trueOffset += distance(truth, P);
  }
  std::sort(errors.begin(), errors.end());
  cell.reached = int(errors.size());
  cell.missFraction = cell.samples ? double(cell.misses) / double(cell.samples) : 0.0;
  if (!errors.empty()) {
    const double n = double(errors.size());
    double mean = 0.0;
    for (double x : errors)
      mean += x;
    cell.meanErrorMm = mean / n;
    cell.p95ErrorMm = errors[std::min(errors.size() - 1, std::size_t(0.95 * n))];
    cell.maxErrorMm = errors.back();
    cell.meanParallaxOffsetMm = parallaxOffset / n;
    cell.meanTrueOffsetMm = trueOffset / n;
  }
  return cell;
}

}  // namespace

ParallaxSurface parallaxPlane(int quads) {
  return gridSurface(false, 0.0, quads);
}

ParallaxSurface parallaxSphere(double radiusMm, int quads) {
  return gridSurface(true, radiusMm, quads);
}

ParallaxCell measureParallaxLookup(const ParallaxSurface& surface, float depthMm, float refractiveIndex,
                                   float viewAngleDeg, int samplePoints, float maxTransmissionMm) {
  const subsurface::TriangleBvh outer(surface.positions, surface.triangles);
  return measure(surface, outer, innerBvh(surface, depthMm), depthMm, refractiveIndex, viewAngleDeg,
                 samplePoints, maxTransmissionMm);
}

std::vector<ParallaxRow> studyParallax(const std::vector<ParallaxSurface>& surfaces,
                                       const ParallaxStudyConfig& config) {
  std::vector<ParallaxRow> rows;
  for (const ParallaxSurface& s : surfaces) {
    const subsurface::TriangleBvh outer(s.positions, s.triangles);
    for (const float depth : config.depthsMm) {
      const subsurface::TriangleBvh inner = innerBvh(s, depth);
      for (const float index : config.refractiveIndices) {
        ParallaxRow row{s.name, s.what, depth, index, {}};
        for (const float angle : config.viewAnglesDeg)
          row.cells.push_back(
              measure(s, outer, inner, depth, index, angle, config.samplePoints, config.maxTransmissionMm));
        rows.push_back(std::move(row));
      }
    }
  }
  return rows;
}

}  // namespace tissue::studies
