#include "uv_layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace tissue::datagen {
namespace {

/// Side of one liver chart in UV units: three charts and four gutters across.
constexpr double kLiverChartUv = (1.0 - 4.0 * kGutterUv) / 3.0;
/// Bottom of the two rows of liver charts (the 3 x 2 block is centred vertically).
constexpr double kLiverRowsBottom = 0.5 - (2.0 * kLiverChartUv + kGutterUv) / 2.0;

/// UV per mm for the patch and the tube (isotropic texels).
constexpr double kPatchUvPerMm = (1.0 - 2.0 * kGutterUv) / kPatchWidthMm;
constexpr double kTubeCircumferenceUv =
    2.0 * std::numbers::pi * kTubeMeanRadiusMm * (1.0 - 2.0 * kGutterUv) / kTubeLengthMm;

Eigen::Vector2d liverChartOrigin(int face) {
  const int column = face % 3, row = face / 3;
  return {kGutterUv + column * (kLiverChartUv + kGutterUv),
          kLiverRowsBottom + row * (kLiverChartUv + kGutterUv)};
}

/// Outward normal and u axis of each cube face; v = normal x u, so u x v = normal.
struct FaceAxes {
  Eigen::Vector3d normal, u;
};
FaceAxes faceAxes(int face) {
  switch (face) {
    case 0:
      return {{1, 0, 0}, {0, 0, -1}};
    case 1:
      return {{-1, 0, 0}, {0, 0, 1}};
    case 2:
      return {{0, 1, 0}, {1, 0, 0}};
    case 3:
      return {{0, -1, 0}, {1, 0, 0}};
    case 4:
      return {{0, 0, 1}, {1, 0, 0}};
    default:
      return {{0, 0, -1}, {-1, 0, 0}};
  }
}

Eigen::Vector3d liverPattern(double u, double v) {
  // Step 1: the nearest chart (distance to its square; first chart wins ties).
  int best = 0;
  double bestDistance = 1e30;
  for (int face = 0; face < 6; ++face) {
    const Eigen::Vector2d o = liverChartOrigin(face);
    const double dx = std::max({o.x() - u, 0.0, u - o.x() - kLiverChartUv});
    const double dy = std::max({o.y() - v, 0.0, v - o.y() - kLiverChartUv});
    const double d = dx * dx + dy * dy;
    if (d < bestDistance) {
      bestDistance = d;
      best = face;
    }
  }
  // Step 2: face parameters, extrapolated a little into the gutter, then onto the sphere.
  const Eigen::Vector2d o = liverChartOrigin(best);
  const double s = std::clamp((u - o.x()) / kLiverChartUv, -0.1, 1.1);
  const double t = std::clamp((v - o.y()) / kLiverChartUv, -0.1, 1.1);
  return cubeToSphere(cubeFacePoint(best, s, t)).normalized() * kLiverPatternRadiusMm;
}

}  // namespace

const char* meshName(MeshKind kind) {
  switch (kind) {
    case MeshKind::kPatch:
      return "patch";
    case MeshKind::kLiver:
      return "liver";
    case MeshKind::kTube:
      return "tube";
  }
  return "unknown";
}

Float2 patchUv(double xMm, double yMm) {
  return {float(kGutterUv + (xMm + 0.5 * kPatchWidthMm) * kPatchUvPerMm), float(0.5 + yMm * kPatchUvPerMm)};
}

Float2 liverUv(int face, double s, double t) {
  const Eigen::Vector2d o = liverChartOrigin(face);
  return {float(o.x() + s * kLiverChartUv), float(o.y() + t * kLiverChartUv)};
}

Eigen::Vector3d cubeFacePoint(int face, double s, double t) {
  const FaceAxes a = faceAxes(face);
  const Eigen::Vector3d v = a.normal.cross(a.u);
  return a.normal + (2.0 * s - 1.0) * a.u + (2.0 * t - 1.0) * v;
}

Eigen::Vector3d cubeToSphere(const Eigen::Vector3d& c) {
  const Eigen::Vector3d q = c.cwiseProduct(c);
  return {c.x() * std::sqrt(std::max(0.0, 1.0 - q.y() / 2 - q.z() / 2 + q.y() * q.z() / 3)),
          c.y() * std::sqrt(std::max(0.0, 1.0 - q.z() / 2 - q.x() / 2 + q.z() * q.x() / 3)),
          c.z() * std::sqrt(std::max(0.0, 1.0 - q.x() / 2 - q.y() / 2 + q.x() * q.y() / 3))};
}

Float2 tubeUv(double aroundFraction, double alongFraction) {
  const double u0 = 0.5 - 0.5 * kTubeCircumferenceUv;
  return {float(u0 + aroundFraction * kTubeCircumferenceUv),
          float(kGutterUv + alongFraction * (1.0 - 2.0 * kGutterUv))};
}

Eigen::Vector3d patternPoint(MeshKind kind, double u, double v) {
  switch (kind) {
    case MeshKind::kPatch:
      return {(u - kGutterUv) / kPatchUvPerMm - 0.5 * kPatchWidthMm, (v - 0.5) / kPatchUvPerMm, 0.0};
    case MeshKind::kLiver:
      return liverPattern(u, v);
    case MeshKind::kTube: {
      // Outside the chart in u the angle just keeps turning: the pattern wraps continuously.
      const double angle =
          2.0 * std::numbers::pi * (u - (0.5 - 0.5 * kTubeCircumferenceUv)) / kTubeCircumferenceUv;
      const double along = (v - kGutterUv) / (1.0 - 2.0 * kGutterUv) * kTubeLengthMm;
      return {kTubeMeanRadiusMm * std::cos(angle), kTubeMeanRadiusMm * std::sin(angle), along};
    }
  }
  return Eigen::Vector3d::Zero();
}

}  // namespace tissue::datagen
