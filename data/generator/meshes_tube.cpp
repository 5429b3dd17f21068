#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "meshes.h"
#include "uv_layout.h"

namespace tissue::datagen {
namespace {

/// Centreline point (mm) at parameter t in [0, 1]: a gentle S-curve in x-y with a slight rise.
Eigen::Vector3d centreline(double t) {
  const double pi = std::numbers::pi;
  return {140.0 * t, 18.0 * std::sin(pi * t) - 6.0 * std::sin(2.0 * pi * t), 8.0 * std::sin(pi * t)};
}

/// Unit tangent of the centreline at t (central difference).
Eigen::Vector3d centrelineTangent(double t) {
  constexpr double h = 1e-5;
  return (centreline(t + h) - centreline(t - h)).normalized();
}

/// Tube radius (mm) at parameter t: slowly varying between about 8 and 12 mm (peristaltic waves).
double tubeRadius(double t) {
  const double pi = std::numbers::pi;
  return 10.0 + 1.5 * std::sin(2.0 * pi * 2.5 * t) + 0.5 * std::sin(2.0 * pi * 5.3 * t + 1.0);
}

}  // namespace

UvMesh makeTube() {
  UvMesh mesh;
  // Step 1: ring centres and their cumulative arc length (for v).
  std::vector<double> arc(kTubeRings, 0.0);
  for (int j = 1; j < kTubeRings; ++j) {
    arc[j] = arc[j - 1] +
             (centreline(double(j) / (kTubeRings - 1)) - centreline(double(j - 1) / (kTubeRings - 1))).norm();
  }
  // Step 2: rings in a parallel-transport frame (T, N, B right-handed), so the tube does not twist.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  for (int j = 0; j < kTubeRings; ++j) {
    const double t = double(j) / (kTubeRings - 1);
    const Eigen::Vector3d tangent = centrelineTangent(t);
    normal = (normal - normal.dot(tangent) * tangent).normalized();
    const Eigen::Vector3d binormal = tangent.cross(normal);
    for (int i = 0; i < kTubeAround; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / kTubeAround;
      const Eigen::Vector3d p =
          centreline(t) + tubeRadius(t) * (std::cos(angle) * normal + std::sin(angle) * binormal);
      mesh.positions.push_back({float(p.x()), float(p.y()), float(p.z())});
    }
    // One more UV per ring than positions: the seam column u = 1 duplicates u = 0.
    for (int i = 0; i <= kTubeAround; ++i) {
      mesh.uvs.push_back(tubeUv(double(i) / kTubeAround, arc[j] / arc.back()));
    }
  }
  // Step 3: quads between rings; around x along points outward, so these are counter-clockwise.
  for (int j = 0; j + 1 < kTubeRings; ++j) {
    for (int i = 0; i < kTubeAround; ++i) {
      const auto v00 = std::uint32_t(j * kTubeAround + i);
      const auto v10 = std::uint32_t(j * kTubeAround + (i + 1) % kTubeAround);
      const auto v01 = v00 + kTubeAround, v11 = v10 + kTubeAround;
      const auto t00 = std::uint32_t(j * (kTubeAround + 1) + i), t10 = t00 + 1;
      const auto t01 = t00 + kTubeAround + 1, t11 = t10 + kTubeAround + 1;
      mesh.triangles.push_back({v00, v10, v11});
      mesh.uvTriangles.push_back({t00, t10, t11});
      mesh.triangles.push_back({v00, v11, v01});
      mesh.uvTriangles.push_back({t00, t11, t01});
    }
  }
  return mesh;
}

}  // namespace tissue::datagen
