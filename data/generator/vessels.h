#pragma once
/// \file
/// Branching vessel networks on a pattern surface (plane, cylinder or sphere, in mm) and their
/// distance fields. Each network grows by random walks with tapering radius that branch at random
/// (a stochastic L-system-like growth), as the veins of François et al. 2006 Fig. 4(a) and the
/// green/blue channels of Norberg 2010 Fig. 2(a).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace tissue::datagen {

/// The surface the vessels grow on (a closed set of simple shapes).
enum class PatternShape { kPlane, kCylinder, kSphere };

/// A pattern surface: the plane z = 0 limited to |x| <= halfExtent.x, |y| <= halfExtent.y; a
/// cylinder of `radius` around z with z in [0, length]; or a sphere of `radius` at the origin.
struct PatternSurface {
  PatternShape shape = PatternShape::kPlane;
  double radius = 10.0;                       ///< mm (cylinder, sphere)
  double length = 150.0;                      ///< mm (cylinder)
  Eigen::Vector2d halfExtent = {40.0, 30.0};  ///< mm (plane)
};

/// How a network grows.
struct VesselGrowth {
  int roots = 4;                    ///< independent trees
  double rootRadiusMm = 1.0;        ///< radius where a tree starts, mm
  double minRadiusMm = 0.15;        ///< a branch stops below this radius, mm
  double stepMm = 0.8;              ///< walk step, mm
  double taperPerStep = 0.994;      ///< radius factor per step
  double branchProbability = 0.05;  ///< per step
  double wiggle = 0.18;             ///< standard random turn per step, rad
  int maxSegments = 40000;          ///< safety cap on the whole network
  std::uint64_t seed = 1;
};

/// One straight piece of vessel with linearly varying radius.
struct VesselSegment {
  Eigen::Vector3d a, b;  ///< end points, mm
  double ra = 0.0;       ///< radius at a, mm
  double rb = 0.0;       ///< radius at b, mm
};

/// Grows a vessel network on `surface`.
std::vector<VesselSegment> growVessels(const PatternSurface& surface, const VesselGrowth& growth);

/// A vessel network with a uniform grid over its segments for fast nearest-vessel queries.
class VesselField {
 public:
  /// Builds the grid; `influenceMm` extends every segment's radius for soft falloffs.
  VesselField(std::vector<VesselSegment> segments, double influenceMm);

  /// Cross-section profile at `p` (mm): max over segments of sqrt(1 - (d / r)^2) for distance
  /// d < radius r (a round vessel's relative thickness), 0 outside every vessel.
  double profile(const Eigen::Vector3d& p) const;

  /// Soft halo at `p`: max over segments of exp(-(d / (r + influence))^2 * 3), for colour bleeding.
  double halo(const Eigen::Vector3d& p) const;

 private:
  const std::vector<std::uint32_t>* cellAt(const Eigen::Vector3d& p) const;

  std::vector<VesselSegment> m_segments;
  double m_influence = 0.0;
  double m_cell = 1.0;
  Eigen::Vector3d m_origin = Eigen::Vector3d::Zero();
  Eigen::Vector3i m_dims = Eigen::Vector3i::Ones();
  std::vector<std::vector<std::uint32_t>> m_cells;
};

}  // namespace tissue::datagen
