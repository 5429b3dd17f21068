// Kinematic contact kernels: closest core point, signed distance, projection out of the tool.
#include "tissue/sim/contact.h"

#include <algorithm>
#include <cmath>

namespace tissue::sim {

Vec3d normalizedOr(const Vec3d& a, const Vec3d& fallback) {
  const double len = length(a);
  return len > 0.0 && std::isfinite(len) ? (1.0 / len) * a : fallback;
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Vec3d rotateBetween(const Vec3d& from, const Vec3d& to, const Vec3d& p) {
  const Vec3d k = cross(from, to);
  const double s = length(k), c = dot(from, to);
  if (s < 1e-12) {
    if (c > 0.0) return p;
    // Opposite: a half turn about any axis orthogonal to `from`.
    const Vec3d helper = std::abs(from.x) < 0.9 ? Vec3d{1.0, 0.0, 0.0} : Vec3d{0.0, 1.0, 0.0};
    const Vec3d u = normalizedOr(cross(from, helper));
    return 2.0 * dot(u, p) * u - p;
  }
  // Rodrigues: p cos + (u x p) sin + u (u.p)(1 - cos).
  const Vec3d u = (1.0 / s) * k;
  return c * p + s * cross(u, p) + (dot(u, p) * (1.0 - c)) * u;
}

Vec3d closestCorePoint(const ToolShape& shape, const ToolPose& pose, const Vec3d& x) {
  if (shape.kind == ToolShapeKind::Sphere || shape.length <= 0.0) return pose.position;
  const double half = 0.5 * shape.length;
  const double t = std::clamp(dot(x - pose.position, pose.axis), -half, half);
  return pose.position + t * pose.axis;
}

double signedDistance(const ToolShape& shape, const ToolPose& pose, const Vec3d& x) {
  return length(x - closestCorePoint(shape, pose, x)) - shape.radius;
}

Vec3d toolPointVelocity(const ToolPose& previous, const ToolPose& current, double dt, const Vec3d& x) {
  if (!(dt > 0.0)) return {};
  // Where the tool's material point now at x was: undo the rotation about the centre.
  const Vec3d before = previous.position + rotateBetween(current.axis, previous.axis, x - current.position);
  return (1.0 / dt) * (x - before);
}

Vec3d pushOutOfTool(const ToolShape& shape, const ToolPose& pose, const Vec3d& motion, const Vec3d& point,
                    Vec3d& normal) {
  const double r = shape.radius, r2 = r * r;
  Vec3d x = point;
  Vec3d core = closestCorePoint(shape, pose, x);
  Vec3d d = x - core;
  // A moving tool pushes the points it swept ahead along its motion, onto its leading surface,
  // so that they keep their place across the motion instead of sliding round the tool within
  // one step (the springs, not the projection, move them sideways). A point the sub-move swept
  // was outside at the previous pose: |d + s u| >= r > |d| with u the unit motion and s its
  // length gives d.u > -s/2. A point deeper behind the core (tissue following a retracting
  // tool) was not swept and leaves radially; pushing it through to the leading side would
  // pull the tissue along with the tool.
  const double s = length(motion);
  if (s > 1e-9 * r && dot(d, d) < r2) {
    const Vec3d direction = (1.0 / s) * motion;
    const double b = dot(d, direction), c = dot(d, d) - r2;
    if (b > -0.5 * s) {
      x += (-b + std::sqrt(std::max(0.0, b * b - c))) * direction;
      core = closestCorePoint(shape, pose, x);
      d = x - core;
    }
  }
  // Then radially (a capsule's core point moves along the ray; a resting tool pushes radially).
  // A point exactly on the core leaves along +x (any direction is as good; sub-moves shorter
  // than the radius keep points off the core).
  normal = normalizedOr(d, Vec3d{1.0, 0.0, 0.0});
  if (dot(d, d) < r2) x = core + r * normal;
  return x;
}

ProjectionResult projectOutOfTool(const ToolShape& shape, const ToolPose& pose, const ToolPose& previous,
                                  double dt, std::span<const double> mass, std::span<const double> invMass,
                                  std::span<Vec3d> x, std::span<Vec3d> v) {
  ProjectionResult result;
  const double r = shape.radius, r2 = r * r;
  // Cheap reject: points farther from the centre than the capsule's half length plus radius.
  const double reach = r + 0.5 * (shape.kind == ToolShapeKind::Capsule ? shape.length : 0.0);
  const double reach2 = reach * reach;
  const Vec3d motion = pose.position - previous.position;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec3d fromCentre = x[k] - pose.position;
    if (dot(fromCentre, fromCentre) >= reach2 || invMass[k] == 0.0) continue;
    const Vec3d d = x[k] - closestCorePoint(shape, pose, x[k]);
    if (dot(d, d) >= r2) continue;
    Vec3d n;
    x[k] = pushOutOfTool(shape, pose, motion, x[k], n);
    // Remove the inward normal velocity relative to the tool's surface point.
    const Vec3d u = toolPointVelocity(previous, pose, dt, x[k]);
    const double vn = dot(v[k] - u, n);
    if (vn < 0.0) {
      v[k] -= vn * n;
      result.impulse += (-vn * mass[k]) * n;
    }
    ++result.projected;
  }
  return result;
}

namespace {

/// Closest points of segments [p0, p1] and [a, b]: parameters s on the first and t on the
/// second, in [0, 1] (Ericson, Real-Time Collision Detection, §5.1.9).
void closestSegmentParameters(const Vec3d& p0, const Vec3d& p1, const Vec3d& a, const Vec3d& b, double& s,
                              double& t) {
  const Vec3d d1 = p1 - p0, d2 = b - a, r = p0 - a;
  const double aa = dot(d1, d1), ee = dot(d2, d2), f = dot(d2, r);
  if (aa <= 1e-30 && ee <= 1e-30) {
    s = t = 0.0;
  } else if (aa <= 1e-30) {
    s = 0.0;
    t = std::clamp(f / ee, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (ee <= 1e-30) {
      t = 0.0;
      s = std::clamp(-c / aa, 0.0, 1.0);
    } else {
      const double bb = dot(d1, d2), denom = aa * ee - bb * bb;
      s = denom > 0.0 ? std::clamp((bb * f - c * ee) / denom, 0.0, 1.0) : 0.0;
      t = (bb * s + f) / ee;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / aa, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((bb - c) / aa, 0.0, 1.0);
      }
    }
  }
}

}  // namespace

ProjectionResult stopSweptPoints(const ToolShape& shape, const ToolPose& pose, const ToolPose& next,
                                 double dt, std::span<const double> mass, std::span<const double> invMass,
                                 std::span<const Vec3d> xBefore, std::span<Vec3d> x, std::span<Vec3d> v) {
  ProjectionResult result;
  const double r = shape.radius;
  const double half = shape.kind == ToolShapeKind::Capsule ? 0.5 * shape.length : 0.0;
  const Vec3d a = pose.position - half * pose.axis, b = pose.position + half * pose.axis;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (invMass[k] == 0.0) continue;
    const Vec3d p0 = xBefore[k], p1 = x[k], d = p1 - p0;
    // Cheap reject: the step's bounding sphere misses the tool's.
    const Vec3d mid = 0.5 * (p0 + p1) - pose.position;
    const double reach = r + half + 0.5 * length(d);
    if (dot(mid, mid) >= reach * reach) continue;
    double s = 0.0, t = 0.0;
    closestSegmentParameters(p0, p1, a, b, s, t);
    const Vec3d core = a + t * (b - a);
    if (!(length(p0 + s * d - core) < r)) continue;  // the step never comes within the radius
    // Entry: the first parameter u in [0, s] at distance r from `core` (0 when p0 is inside).
    const Vec3d core0 = closestCorePoint(shape, pose, p0), core1 = closestCorePoint(shape, pose, p1);
    const Vec3d w = p0 - core;
    const double qa = dot(d, d), qb = 2.0 * dot(w, d), qc = dot(w, w) - r * r;
    const double disc = qb * qb - 4.0 * qa * qc;
    double u = 0.0;
    if (qc > 0.0 && qa > 0.0 && disc >= 0.0) u = std::clamp((-qb - std::sqrt(disc)) / (2.0 * qa), 0.0, s);
    const Vec3d entry = p0 + u * d;
    const Vec3d entryCore = closestCorePoint(shape, pose, entry);
    const Vec3d n = normalizedOr(entry - entryCore, normalizedOr(p0 - core0));
    // Steps that end inside near where they entered (a point resting on the tool sliding along
    // it) are left to the radial projection; steps that end inside more than 60 degrees round
    // from their entry, or pass right through, stop at the entry.
    const bool endsInside = length(p1 - core1) < r;
    const bool passedThrough = !endsInside && s > 0.0 && s < 1.0 && length(p0 - core0) >= r * (1.0 - 1e-9);
    if (endsInside && dot(normalizedOr(p1 - core1, n), n) >= 0.5) continue;
    if (!endsInside && !passedThrough) continue;
    x[k] = entryCore + r * n;
    const Vec3d tool = toolPointVelocity(pose, next, dt, x[k]);
    const double vn = dot(v[k] - tool, n);
    if (vn < 0.0) {
      v[k] -= vn * n;
      result.impulse += (-vn * mass[k]) * n;
    }
    ++result.projected;
  }
  return result;
}

}  // namespace tissue::sim
