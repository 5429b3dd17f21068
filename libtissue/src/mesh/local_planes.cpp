#include "tissue/mesh/local_planes.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

/// The least-squares plane of a point set from its moments about `origin` (François §2.2:
/// "a least square fitting algorithm operating on the vertices ... in a spherical
/// neighbourhood"): it passes through the centroid c, its normal N_S is the eigenvector of the
/// covariance with the smallest eigenvalue, oriented like the vertex normal N_V. The plane is
/// stored as (N_S, d) with P_V = V + d N_V on it (eq. 14).
Float4 planeFromMoments(double count, const double s[3], const double ss[6], Float3 origin, Float3 vertex,
                        Float3 vertexNormal) {
  const Eigen::Vector3d mean(s[0] / count, s[1] / count, s[2] / count);
  Eigen::Matrix3d cov;
  cov << ss[0], ss[1], ss[2], ss[1], ss[3], ss[4], ss[2], ss[4], ss[5];
  cov = cov / count - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov, Eigen::ComputeEigenvectors);
  Eigen::Vector3d n = solver.eigenvectors().col(0);  // eigenvalues ascend
  const Eigen::Vector3d nv(vertexNormal.x, vertexNormal.y, vertexNormal.z);
  if (n.dot(nv) < 0.0) n = -n;
  // Offset along N_V to the plane: solve N_S . (V + d N_V - c) = 0. Where N_V is nearly
  // parallel to the plane (a fold) fall back to the distance along N_S.
  const Eigen::Vector3d c = Eigen::Vector3d(origin.x, origin.y, origin.z) + mean;
  const Eigen::Vector3d v(vertex.x, vertex.y, vertex.z);
  const double along = n.dot(nv);
  const double d = n.dot(c - v) / (along > 0.1 ? along : 1.0);
  return {float(n.x()), float(n.y()), float(n.z()), float(d)};
}

void accumulate(double s[3], double ss[6], Float3 p, Float3 origin, double sign) {
  const double x = double(p.x) - double(origin.x), y = double(p.y) - double(origin.y),
               z = double(p.z) - double(origin.z);
  s[0] += sign * x, s[1] += sign * y, s[2] += sign * z;
  ss[0] += sign * x * x, ss[1] += sign * x * y, ss[2] += sign * x * z;
  ss[3] += sign * y * y, ss[4] += sign * y * z, ss[5] += sign * z * z;
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
  for (std::size_t v = 0; v < hoods.vertexCount(); ++v) {
    double s[3] = {0, 0, 0}, ss[6] = {0, 0, 0, 0, 0, 0};
    const Float3 origin = positions[v];  // conditioning: moments about the vertex itself
    for (auto k = hoods.offsets[v]; k < hoods.offsets[v + 1]; ++k)
      accumulate(s, ss, positions[hoods.indices[k]], origin, 1.0);
    planes[v] = planeFromMoments(double(hoods.offsets[v + 1] - hoods.offsets[v]), s, ss, origin, positions[v],
                                 normals[v]);
  }
}

IncrementalPlaneFitter::IncrementalPlaneFitter(std::span<const Float3> restPositions,
                                               std::span<const Triangle> triangles,
                                               const PlaneFitSettings& settings)
    : m_settings(settings),
      m_hoods(findNeighbourhoods(restPositions, settings.radiusMm(), triangles)),
      m_origin(restPositions.begin(), restPositions.end()),
      m_moments(restPositions.size()),
      m_fitted(restPositions.begin(), restPositions.end()),
      m_planes(restPositions.size()),
      m_dirtyStamp(restPositions.size(), 0) {}

void IncrementalPlaneFitter::fitAll(std::span<const Float3> positions, std::span<const Float3> normals) {
  for (std::size_t v = 0; v < m_hoods.vertexCount(); ++v) {
    Moments& m = m_moments[v];
    std::fill(std::begin(m.s), std::end(m.s), 0.0);
    std::fill(std::begin(m.ss), std::end(m.ss), 0.0);
    for (auto k = m_hoods.offsets[v]; k < m_hoods.offsets[v + 1]; ++k)
      accumulate(m.s, m.ss, positions[m_hoods.indices[k]], m_origin[v], 1.0);
    solvePlane(std::uint32_t(v), positions, normals);
  }
  std::copy(positions.begin(), positions.end(), m_fitted.begin());
}

void IncrementalPlaneFitter::solvePlane(std::uint32_t v, std::span<const Float3> positions,
                                        std::span<const Float3> normals) {
  const Moments& m = m_moments[v];
  m_planes[v] = planeFromMoments(double(m_hoods.offsets[v + 1] - m_hoods.offsets[v]), m.s, m.ss, m_origin[v],
                                 positions[v], normals[v]);
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
  // A global deformation touches every plane many times over: updating moments vertex by
  // vertex would cost more than summing each neighbourhood once, so fit from scratch then.
  std::size_t work = 0;
  for (auto v : movedVertices)
    work += m_hoods.offsets[v + 1] - m_hoods.offsets[v];
  if (2 * work > m_hoods.indices.size()) {
    fitAll(positions, normals);
    return {movedVertices.size(), m_hoods.vertexCount()};
  }
  // Step 1: a moved vertex swaps its old position for its new one in the moments of every
  // plane whose neighbourhood holds it (the relation is symmetric, so these are its own
  // neighbours), and marks those planes dirty.
  if (++m_stamp == 0) {  // wrapped: clear the stamps once every 2^32 updates
    std::fill(m_dirtyStamp.begin(), m_dirtyStamp.end(), 0u);
    m_stamp = 1;
  }
  m_dirtyList.clear();
  for (auto v : movedVertices) {
    for (auto k = m_hoods.offsets[v]; k < m_hoods.offsets[v + 1]; ++k) {
      const auto j = m_hoods.indices[k];
      Moments& m = m_moments[j];
      accumulate(m.s, m.ss, m_fitted[v], m_origin[j], -1.0);
      accumulate(m.s, m.ss, positions[v], m_origin[j], 1.0);
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
