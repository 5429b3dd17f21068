#include "tissue/mesh/local_planes.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "fixed_moments.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

struct IncrementalPlaneFitter::Moments : detail::FixedSums {};

namespace {

/// The least-squares plane of a point set from its exact moments (François §2.2: "a least
/// square fitting algorithm operating on the vertices ... in a spherical neighbourhood"): it
/// passes through the centroid c, its normal N_S is the eigenvector of the covariance with the
/// smallest eigenvalue, oriented like the vertex normal N_V. Stored as (N_S, d) with
/// P_V = V + d N_V on the plane (eq. 14).
Float4 planeFromSums(std::int64_t count, const detail::FixedSums& m, Float3 origin, Float3 vertex,
                     Float3 vertexNormal) {
  using detail::Int128;
  // n^2 C = n S2 - S1 S1^T, exact in 128-bit integers; one rounding when converted.
  const Int128 n = count;
  const auto c = [&](int k, int i, int j) { return double(n * m.ss[k] - Int128(m.s[i]) * m.s[j]); };
  const double scale = 1.0 / (double(count) * double(count) * detail::kQuantumPerMm * detail::kQuantumPerMm);
  Eigen::Matrix3d cov;
  cov << c(0, 0, 0), c(1, 0, 1), c(2, 0, 2), c(1, 0, 1), c(3, 1, 1), c(4, 1, 2), c(2, 0, 2), c(4, 1, 2),
      c(5, 2, 2);
  cov *= scale;  // mm^2
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov, Eigen::ComputeEigenvectors);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);  // eigenvalues ascend
  const Eigen::Vector3d nv(vertexNormal.x, vertexNormal.y, vertexNormal.z);
  if (normal.dot(nv) < 0.0) normal = -normal;
  // Offset along N_V to the plane: solve N_S . (V + d N_V - c) = 0. Where N_V is nearly
  // parallel to the plane (a fold) fall back to the distance along N_S.
  const double inv = 1.0 / (double(count) * detail::kQuantumPerMm);
  const Eigen::Vector3d centroid(double(origin.x) + double(m.s[0]) * inv,
                                 double(origin.y) + double(m.s[1]) * inv,
                                 double(origin.z) + double(m.s[2]) * inv);
  const Eigen::Vector3d v(vertex.x, vertex.y, vertex.z);
  const double along = normal.dot(nv);
  const double d = normal.dot(centroid - v) / (along > 0.1 ? along : 1.0);
  return {float(normal.x()), float(normal.y()), float(normal.z()), float(d)};
}

/// The quantisation origin: the centre of the bounding box, rounded to the quantum so that
/// quantising about it is an exact integer translation of quantising about any other.
Float3 quantisationOrigin(std::span<const Float3> positions) {
  if (positions.empty()) return {};
  Float3 lo = positions[0], hi = positions[0];
  for (const auto& p : positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const auto snap = [](float a, float b) {
    return float(std::round(0.5 * (double(a) + double(b)) * detail::kQuantumPerMm) / detail::kQuantumPerMm);
  };
  return {snap(lo.x, hi.x), snap(lo.y, hi.y), snap(lo.z, hi.z)};
}

std::vector<detail::FixedPoint> quantiseAll(std::span<const Float3> positions, Float3 origin) {
  std::vector<detail::FixedPoint> q(positions.size());
  for (std::size_t i = 0; i < q.size(); ++i)
    q[i] = detail::quantise(positions[i], origin);
  return q;
}

}  // namespace

PlaneDeviation comparePlanes(std::span<const Float4> a, std::span<const Float4> b) {
  PlaneDeviation dev;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const Eigen::Vector3d na(a[i].x, a[i].y, a[i].z), nb(b[i].x, b[i].y, b[i].z);
    // atan2(|a x b|, a.b) keeps full precision for tiny angles, where acos(a.b) cannot.
    dev.maxAngleRad = std::max(dev.maxAngleRad, std::atan2(na.cross(nb).norm(), na.dot(nb)));
    dev.maxOffsetMm = std::max(dev.maxOffsetMm, std::abs(double(a[i].w) - double(b[i].w)));
  }
  return dev;
}

void fitVertexPlanes(std::span<const Float3> positions, std::span<const Float3> normals,
                     const Neighbourhoods& hoods, std::span<Float4> planes) {
  const Float3 origin = quantisationOrigin(positions);
  const auto q = quantiseAll(positions, origin);
  for (std::size_t v = 0; v < hoods.vertexCount(); ++v) {
    detail::FixedSums sums;
    for (auto k = hoods.offsets[v]; k < hoods.offsets[v + 1]; ++k)
      sums.add(q[hoods.indices[k]], 1);
    planes[v] = planeFromSums(std::int64_t(hoods.offsets[v + 1] - hoods.offsets[v]), sums, origin,
                              positions[v], normals[v]);
  }
}

IncrementalPlaneFitter::IncrementalPlaneFitter(std::span<const Float3> restPositions,
                                               std::span<const Triangle> triangles,
                                               const PlaneFitSettings& settings)
    : m_settings(settings),
      m_hoods(findNeighbourhoods(restPositions, settings.radiusMm(), triangles)),
      m_origin(quantisationOrigin(restPositions)),
      m_moments(restPositions.size()),
      m_fitted(restPositions.begin(), restPositions.end()),
      m_planes(restPositions.size()),
      m_dirtyStamp(restPositions.size(), 0) {}

IncrementalPlaneFitter::~IncrementalPlaneFitter() = default;
IncrementalPlaneFitter::IncrementalPlaneFitter(IncrementalPlaneFitter&&) noexcept = default;
IncrementalPlaneFitter& IncrementalPlaneFitter::operator=(IncrementalPlaneFitter&&) noexcept = default;

void IncrementalPlaneFitter::fitAll(std::span<const Float3> positions, std::span<const Float3> normals) {
  const auto q = quantiseAll(positions, m_origin);
  for (std::size_t v = 0; v < m_hoods.vertexCount(); ++v) {
    Moments& m = m_moments[v];
    m = Moments{};
    for (auto k = m_hoods.offsets[v]; k < m_hoods.offsets[v + 1]; ++k)
      m.add(q[m_hoods.indices[k]], 1);
    solvePlane(std::uint32_t(v), positions, normals);
  }
  std::copy(positions.begin(), positions.end(), m_fitted.begin());
}

void IncrementalPlaneFitter::solvePlane(std::uint32_t v, std::span<const Float3> positions,
                                        std::span<const Float3> normals) {
  m_planes[v] = planeFromSums(std::int64_t(m_hoods.offsets[v + 1] - m_hoods.offsets[v]), m_moments[v],
                              m_origin, positions[v], normals[v]);
}

RefitStats IncrementalPlaneFitter::update(std::span<const Float3> positions, std::span<const Float3> normals,
                                          float toleranceMm) {
  std::vector<std::uint32_t> moved;
  const float tol2 = toleranceMm * toleranceMm;
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    const Float3 d = positions[v] - m_fitted[v];
    if (dot(d, d) > tol2) moved.push_back(v);
  }
  return updateMoved(positions, normals, moved);
}

RefitStats IncrementalPlaneFitter::updateMoved(std::span<const Float3> positions,
                                               std::span<const Float3> normals,
                                               std::span<const std::uint32_t> movedVertices) {
  // A global deformation touches every plane many times over: adding differences vertex by
  // vertex would cost more than summing each neighbourhood once, so sum from scratch then.
  std::size_t work = 0;
  for (auto v : movedVertices)
    work += m_hoods.offsets[v + 1] - m_hoods.offsets[v];
  if (2 * work > m_hoods.indices.size()) {
    fitAll(positions, normals);
    return {movedVertices.size(), m_hoods.vertexCount()};
  }
  // Step 1: a moved vertex adds (new moments - old moments) to every plane whose neighbourhood
  // holds it (the relation is symmetric, so these are its own neighbours) and marks it dirty.
  if (++m_stamp == 0) {  // wrapped: clear the stamps once every 2^32 updates
    std::fill(m_dirtyStamp.begin(), m_dirtyStamp.end(), 0u);
    m_stamp = 1;
  }
  m_dirtyList.clear();
  for (auto v : movedVertices) {
    detail::FixedSums delta;
    delta.add(detail::quantise(positions[v], m_origin), 1);
    delta.add(detail::quantise(m_fitted[v], m_origin), -1);
    for (auto k = m_hoods.offsets[v]; k < m_hoods.offsets[v + 1]; ++k) {
      const auto j = m_hoods.indices[k];
      m_moments[j].add(delta);
      if (m_dirtyStamp[j] != m_stamp) {
        m_dirtyStamp[j] = m_stamp;
        m_dirtyList.push_back(j);
      }
    }
    m_fitted[v] = positions[v];
  }
  // Step 2: only the dirty planes solve their eigenproblem again.
  for (auto j : m_dirtyList)
    solvePlane(j, positions, normals);
  return {movedVertices.size(), m_dirtyList.size()};
}

}  // namespace tissue::mesh
