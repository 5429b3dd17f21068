#pragma once
/// \file
/// Stateless kernels of kinematic contact with a rigid tool: the tool's shape and pose, the
/// closest point of its core, and the projection of points out of it (instrument.h runs them).
///
/// The tool is a sphere or a capsule: a core (a point, or a segment) swept by a radius. A point
/// closer than the radius to the core is inside; projecting it moves it along the core-to-point
/// direction onto the surface and removes its inward normal velocity relative to the tool.

#include <cstdint>
#include <span>

#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// The tool shapes (a closed set).
enum class ToolShapeKind {
  Sphere,   ///< radius only
  Capsule,  ///< a cylinder of `length` along the pose's axis, capped by hemispheres of `radius`
};

/// A rigid tool tip.
struct ToolShape {
  ToolShapeKind kind = ToolShapeKind::Sphere;
  double radius = 5.0;  ///< mm, > 0
  double length = 0.0;  ///< mm, capsule only: distance between the two cap centres, >= 0
};

/// Where the tool is: its centre and, for a capsule, the direction of its core.
struct ToolPose {
  Vec3d position{};           ///< mm, centre of the sphere or of the capsule's core
  Vec3d axis{0.0, 0.0, 1.0};  ///< unit, capsule core direction (ignored for a sphere)
};

/// Unit vector along `a`; +z when `a` has no length.
Vec3d normalizedOr(const Vec3d& a, const Vec3d& fallback = {0.0, 0.0, 1.0});
/// Cross product a x b.
Vec3d cross(const Vec3d& a, const Vec3d& b);
/// Rotates `p` by the smallest rotation taking unit `from` to unit `to` (Rodrigues' formula;
/// for opposite vectors, a half turn about an axis orthogonal to `from`).
Vec3d rotateBetween(const Vec3d& from, const Vec3d& to, const Vec3d& p);

/// The point of the tool's core closest to `x` (mm): the centre for a sphere, the clamped
/// projection on the segment for a capsule.
Vec3d closestCorePoint(const ToolShape& shape, const ToolPose& pose, const Vec3d& x);

/// Distance (mm) from `x` to the tool's surface, negative inside.
double signedDistance(const ToolShape& shape, const ToolPose& pose, const Vec3d& x);

/// Velocity (mm/s) of the tool's material point now at `x` (mm) when the tool moved rigidly from
/// `previous` to `current` in `dt` seconds (translation of the centre plus the smallest rotation
/// of the axis); zero when dt <= 0.
Vec3d toolPointVelocity(const ToolPose& previous, const ToolPose& current, double dt, const Vec3d& x);

/// Where projectOutOfTool puts a point `point` (mm) that lies inside the tool at `pose`, the
/// tool having moved by `motion` (mm) since its previous pose: a point the motion swept (one
/// that was outside before: d.u > -|motion|/2 for a sphere, d from the core, u the motion's
/// direction) goes along the motion onto the leading surface; then every point goes radially
/// from the core onto the surface. `normal` receives the outward unit normal there. A point
/// outside is returned unchanged (with its normal).
Vec3d pushOutOfTool(const ToolShape& shape, const ToolPose& pose, const Vec3d& motion, const Vec3d& point,
                    Vec3d& normal);

/// The points one projection touched, and the momentum it gave them.
struct ProjectionResult {
  std::uint32_t projected = 0;  ///< points moved onto the surface
  Vec3d impulse{};              ///< sum of m dv over the projected points, g*mm/s (on the points)
};

/// Projects every point of `x` with `invMass[k] > 0` that lies inside the tool (at `pose`) onto
/// its surface - a point the tool's motion since `previous` swept along that motion (onto its
/// leading side), then along the core-to-point direction (pushOutOfTool) - and removes the inward part of its
/// normal velocity relative to the tool's point velocity (the tool moved from `previous` in `dt` s). Points
/// with invMass 0 (pinned, grasped) are left alone. `mass` in g, positions mm, velocities mm/s. Works on any
/// point set: the simulated vertices, or an embedded surface whose corrections are then scattered to lattice
/// nodes.
ProjectionResult projectOutOfTool(const ToolShape& shape, const ToolPose& pose, const ToolPose& previous,
                                  double dt, std::span<const double> mass, std::span<const double> invMass,
                                  std::span<Vec3d> x, std::span<Vec3d> v);

/// Swept contact for the points' own motion: a point whose step from `xBefore` to `x` (mm) went
/// through the tool at `pose` (entering it and leaving on the far side, or ending inside past
/// the core) is stopped where it entered, on the surface, and loses its inward normal velocity
/// relative to the tool's point velocity (tool moving from `pose` to `next` in `dt` s). Stiff
/// springs under implicit Euler can carry a light vertex farther than the tool's diameter in one
/// step; this keeps it on its side. Points with invMass 0 are left alone.
ProjectionResult stopSweptPoints(const ToolShape& shape, const ToolPose& pose, const ToolPose& next,
                                 double dt, std::span<const double> mass, std::span<const double> invMass,
                                 std::span<const Vec3d> xBefore, std::span<Vec3d> x, std::span<Vec3d> v);

}  // namespace tissue::sim
