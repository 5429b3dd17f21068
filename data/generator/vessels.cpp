#include "vessels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "rng.h"

namespace tissue::datagen {
namespace {

/// Projects `p` onto the surface.
Eigen::Vector3d project(const PatternSurface& s, Eigen::Vector3d p) {
  switch (s.shape) {
    case PatternShape::kPlane:
      p.z() = 0.0;
      return p;
    case PatternShape::kCylinder: {
      const double r = std::hypot(p.x(), p.y());
      return {p.x() * s.radius / r, p.y() * s.radius / r, p.z()};
    }
    case PatternShape::kSphere:
      return p.normalized() * s.radius;
  }
  return p;
}

Eigen::Vector3d surfaceNormal(const PatternSurface& s, const Eigen::Vector3d& p) {
  switch (s.shape) {
    case PatternShape::kPlane:
      return Eigen::Vector3d::UnitZ();
    case PatternShape::kCylinder:
      return Eigen::Vector3d(p.x(), p.y(), 0.0).normalized();
    case PatternShape::kSphere:
      return p.normalized();
  }
  return Eigen::Vector3d::UnitZ();
}

bool inside(const PatternSurface& s, const Eigen::Vector3d& p) {
  constexpr double kMarginMm = 4.0;  // vessels run a little past the border so edges are not bare
  switch (s.shape) {
    case PatternShape::kPlane:
      return std::abs(p.x()) <= s.halfExtent.x() + kMarginMm &&
             std::abs(p.y()) <= s.halfExtent.y() + kMarginMm;
    case PatternShape::kCylinder:
      return p.z() >= -kMarginMm && p.z() <= s.length + kMarginMm;
    case PatternShape::kSphere:
      return true;
  }
  return false;
}

/// A random point and tangent direction on the surface.
std::pair<Eigen::Vector3d, Eigen::Vector3d> randomStart(const PatternSurface& s, Rng& rng) {
  Eigen::Vector3d p;
  switch (s.shape) {
    case PatternShape::kPlane:
      p = {rng.uniform(-s.halfExtent.x(), s.halfExtent.x()), rng.uniform(-s.halfExtent.y(), s.halfExtent.y()),
           0.0};
      break;
    case PatternShape::kCylinder: {
      const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
      p = {std::cos(angle), std::sin(angle), rng.uniform(0.0, s.length)};
      break;
    }
    case PatternShape::kSphere:
      p = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
      break;
  }
  p = project(s, p);
  const Eigen::Vector3d n = surfaceNormal(s, p);
  Eigen::Vector3d d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  d = (d - d.dot(n) * n).normalized();
  return {p, d};
}

/// A branch waiting to grow.
struct Sprout {
  Eigen::Vector3d p, d;
  double radius;
};

}  // namespace

std::vector<VesselSegment> growVessels(const PatternSurface& surface, const VesselGrowth& growth) {
  Rng rng(growth.seed);
  std::vector<VesselSegment> segments;
  std::vector<Sprout> stack;
  for (int r = 0; r < growth.roots; ++r) {
    const auto [p, d] = randomStart(surface, rng);
    stack.push_back({p, d, growth.rootRadiusMm * rng.uniform(0.8, 1.2)});
  }
  // Depth-first growth from an explicit stack: deterministic order, no recursion.
  while (!stack.empty() && int(segments.size()) < growth.maxSegments) {
    Sprout s = stack.back();
    stack.pop_back();
    double turnRate = 0.0;
    while (s.radius >= growth.minRadiusMm && inside(surface, s.p) &&
           int(segments.size()) < growth.maxSegments) {
      // Step 1: turn about the surface normal; the turn rate itself wanders, giving smooth curves.
      const Eigen::Vector3d n = surfaceNormal(surface, s.p);
      turnRate = 0.7 * turnRate + growth.wiggle * rng.uniform(-1.0, 1.0);
      s.d = Eigen::AngleAxisd(turnRate, n) * s.d;
      // Step 2: advance, back onto the surface, and keep the direction tangent.
      const Eigen::Vector3d next = project(surface, s.p + growth.stepMm * s.d);
      const Eigen::Vector3d n2 = surfaceNormal(surface, next);
      const double nextRadius = s.radius * growth.taperPerStep;
      segments.push_back({s.p, next, s.radius, nextRadius});
      s.d = (s.d - s.d.dot(n2) * n2).normalized();
      s.p = next;
      s.radius = nextRadius;
      // Step 3: maybe branch; the child is thinner and leaves at 30-60 degrees (Murray-like split).
      if (rng.uniform() < growth.branchProbability) {
        const double side = rng.uniform() < 0.5 ? -1.0 : 1.0;
        const double angle = side * rng.uniform(0.5, 1.05);
        stack.push_back({s.p, Eigen::AngleAxisd(angle, n2) * s.d, s.radius * rng.uniform(0.55, 0.75)});
        s.radius *= 0.92;
      }
    }
  }
  return segments;
}

VesselField::VesselField(std::vector<VesselSegment> segments, double influenceMm)
    : m_segments(std::move(segments)), m_influence(influenceMm) {
  if (m_segments.empty()) return;
  // Step 1: bounding box of all segments, and a cell size that keeps the grid small.
  double maxRadius = 0.0;
  Eigen::Vector3d lo = m_segments.front().a, hi = lo;
  for (const VesselSegment& s : m_segments) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
    maxRadius = std::max({maxRadius, s.ra, s.rb});
  }
  const double reach = maxRadius + m_influence;
  m_origin = lo - Eigen::Vector3d::Constant(reach);
  const Eigen::Vector3d size = hi - lo + Eigen::Vector3d::Constant(2.0 * reach);
  m_cell = std::max(2.0 * reach, std::cbrt(size.prod() / 200000.0));
  m_dims = (size / m_cell).array().ceil().cast<int>().max(1);
  m_cells.resize(std::size_t(m_dims.prod()));
  // Step 2: each segment goes into every cell its expanded bounding box touches.
  for (std::uint32_t i = 0; i < m_segments.size(); ++i) {
    const VesselSegment& s = m_segments[i];
    const double r = std::max(s.ra, s.rb) + m_influence;
    const Eigen::Vector3d lo3 = (s.a.cwiseMin(s.b) - m_origin).array() - r;
    const Eigen::Vector3d hi3 = (s.a.cwiseMax(s.b) - m_origin).array() + r;
    const Eigen::Vector3i a = (lo3 / m_cell).array().floor().cast<int>().max(0).min(m_dims.array() - 1);
    const Eigen::Vector3i b = (hi3 / m_cell).array().floor().cast<int>().max(0).min(m_dims.array() - 1);
    for (int z = a.z(); z <= b.z(); ++z)
      for (int y = a.y(); y <= b.y(); ++y)
        for (int x = a.x(); x <= b.x(); ++x)
          m_cells[(std::size_t(z) * m_dims.y() + y) * m_dims.x() + x].push_back(i);
  }
}

const std::vector<std::uint32_t>* VesselField::cellAt(const Eigen::Vector3d& p) const {
  if (m_cells.empty()) return nullptr;
  const Eigen::Vector3i c = ((p - m_origin) / m_cell).array().floor().cast<int>();
  if ((c.array() < 0).any() || (c.array() >= m_dims.array()).any()) return nullptr;
  return &m_cells[(std::size_t(c.z()) * m_dims.y() + c.y()) * m_dims.x() + c.x()];
}

double VesselField::profile(const Eigen::Vector3d& p) const {
  const auto* cell = cellAt(p);
  if (!cell) return 0.0;
  double best = 0.0;
  for (std::uint32_t i : *cell) {
    const VesselSegment& s = m_segments[i];
    const Eigen::Vector3d ab = s.b - s.a;
    const double t = std::clamp((p - s.a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    const double r = s.ra + (s.rb - s.ra) * t;
    const double d2 = (s.a + t * ab - p).squaredNorm();
    if (d2 < r * r) best = std::max(best, std::sqrt(1.0 - d2 / (r * r)));
  }
  return best;
}

double VesselField::halo(const Eigen::Vector3d& p) const {
  const auto* cell = cellAt(p);
  if (!cell) return 0.0;
  double best = 0.0;
  for (std::uint32_t i : *cell) {
    const VesselSegment& s = m_segments[i];
    const Eigen::Vector3d ab = s.b - s.a;
    const double t = std::clamp((p - s.a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    const double r = s.ra + (s.rb - s.ra) * t + m_influence;
    const double d2 = (s.a + t * ab - p).squaredNorm();
    if (d2 < r * r) best = std::max(best, std::exp(-3.0 * d2 / (r * r)) - std::exp(-3.0));
  }
  return best / (1.0 - std::exp(-3.0));
}

}  // namespace tissue::datagen
