#include "tissue/mesh/local_planes.h"
#include "tissue/core/vec_math.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>

#include "fixed_moments.h"
#include "tissue/mesh/worker_pool.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

struct IncrementalPlaneFitter::Moments : detail::FixedSums {};

struct IncrementalPlaneFitter::Solved {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();    // unit, unoriented
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // mm
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();     // mm, tolerant mode: mean displacement since
  float tolerancePerRad = 0.0f;                        // mm/rad, 1 / K_j
};

namespace {

/// The least-squares plane of a point set from its exact moments (François §2.2: "a least
/// square fitting algorithm operating on the vertices ... in a spherical neighbourhood"): it
/// passes through the centroid c, its normal N_S is the eigenvector of the covariance with the
/// smallest eigenvalue. Oriented and offset later (orientPlane), from the current vertex.
/// Also returns 1 / K (mm/rad), the displacement per radian of normal error the plane tolerates
/// (first-order perturbation, see IncrementalPlaneFitter in local_planes.h).
struct SolvedPlane {
  Eigen::Vector3d normal;    // unit, unoriented
  Eigen::Vector3d centroid;  // mm
  float tolerancePerRad = 0.0f;
};

SolvedPlane solveSums(std::int64_t count, const detail::FixedSums& m, Float3 origin) {
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
  SolvedPlane out;
  out.normal = solver.eigenvectors().col(0);  // eigenvalues ascend
  const double inv = 1.0 / (double(count) * detail::kQuantumPerMm);
  out.centroid = {double(origin.x) + double(m.s[0]) * inv, double(origin.y) + double(m.s[1]) * inv,
                  double(origin.z) + double(m.s[2]) * inv};
  // theta <= tau K, K^2 = sum_{k=2,3} (l1 + lk) / (lk - l1)^2: a vanishing gap tolerates nothing.
  const Eigen::Vector3d l = solver.eigenvalues();
  const double l1 = std::max(l[0], 0.0), g2 = l[1] - l1, g3 = l[2] - l1;
  if (g2 > 0.0 && g3 > 0.0) {
    const double k2 = (l1 + l[1]) / (g2 * g2) + (l1 + l[2]) / (g3 * g3);
    out.tolerancePerRad = float(1.0 / std::sqrt(k2));
  }
  return out;
}

/// Orients N_S like the vertex normal N_V and stores (N_S, d) with P_V = V + d N_V on the
/// plane (eq. 14).
Float4 orientPlane(const Eigen::Vector3d& solvedNormal, const Eigen::Vector3d& centroid, Float3 vertex,
                   Float3 vertexNormal) {
  Eigen::Vector3d normal = solvedNormal;
  const Eigen::Vector3d nv(vertexNormal.x, vertexNormal.y, vertexNormal.z);
  if (normal.dot(nv) < 0.0) normal = -normal;
  // Offset along N_V to the plane: solve N_S . (V + d N_V - c) = 0. Where N_V is nearly
  // parallel to the plane (a fold) fall back to the distance along N_S.
  const Eigen::Vector3d v(vertex.x, vertex.y, vertex.z);
  const double along = normal.dot(nv);
  const double d = normal.dot(centroid - v) / (along > 0.1 ? along : 1.0);
  return {float(normal.x()), float(normal.y()), float(normal.z()), float(d)};
}

/// The quantisation origin: the centre of the bounding box, rounded to the quantum so that
/// quantising about it is an exact integer translation of quantising about any other.
Float3 quantisationOrigin(std::span<const Float3> positions) {
  if (positions.empty()) return {};
  const Bounds3 box = boundsOf(positions);
  const Float3 lo = box.lo, hi = box.hi;
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
    const auto solved = solveSums(std::int64_t(hoods.offsets[v + 1] - hoods.offsets[v]), sums, origin);
    planes[v] = orientPlane(solved.normal, solved.centroid, positions[v], normals[v]);
  }
}

namespace {

/// Quantising both ends of a displacement moves it by up to sqrt(3) quanta: the tolerance
/// leaves that room so the bound holds for the quantised moments, mm.
constexpr double kQuantisationSlackMm = 1.7320508075688772 / detail::kQuantumPerMm;

// Below this many planes a second thread costs more than it saves.
constexpr std::size_t kMinPlanesPerThread = 2048;

}  // namespace

IncrementalPlaneFitter::IncrementalPlaneFitter(std::span<const Float3> restPositions,
                                               std::span<const Triangle> triangles,
                                               const PlaneFitSettings& settings)
    : m_settings(settings),
      m_hoods(findNeighbourhoods(restPositions, settings.radiusMm(), triangles)),
      m_origin(quantisationOrigin(restPositions)),
      m_moments(restPositions.size()),
      m_solved(restPositions.size()),
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
    solvePlane(std::uint32_t(v));
  }
  std::copy(positions.begin(), positions.end(), m_fitted.begin());
  m_tolerantMode = false;
  orientPlanes(positions, normals);
}

void IncrementalPlaneFitter::solvePlane(std::uint32_t v) {
  const auto s = solveSums(std::int64_t(m_hoods.offsets[v + 1] - m_hoods.offsets[v]), m_moments[v], m_origin);
  m_solved[v] = {s.normal, s.centroid, Eigen::Vector3d::Zero(), s.tolerancePerRad};
}

void IncrementalPlaneFitter::solvePlaneFromScratch(std::uint32_t v, std::span<const Float3> positions,
                                                   std::span<const detail::FixedPoint> quantised) {
  const auto first = m_hoods.offsets[v], last = m_hoods.offsets[v + 1];
  detail::FixedSums sums;  // a local, as in fitAll: the sums stay in registers
  for (auto k = first; k < last; ++k)
    sums.add(quantised[m_hoods.indices[k]], 1);
  for (auto k = first; k < last; ++k)
    m_snapshot[k] = positions[m_hoods.indices[k]];
  static_cast<detail::FixedSums&>(m_moments[v]) = sums;
  solvePlane(v);
}

void IncrementalPlaneFitter::orientPlanes(std::span<const Float3> positions, std::span<const Float3> normals,
                                          WorkerPool* pool) {
  // Every plane, every update: a vertex or its normal can change while its plane's moments do
  // not (below the tolerance), and this costs a few dot products next to an eigenproblem.
  const auto orient = [&](std::size_t b, std::size_t e) {
    for (std::size_t v = b; v < e; ++v) {
      const Solved& s = m_solved[v];
      m_planes[v] = orientPlane(s.normal, m_tolerantMode ? Eigen::Vector3d(s.centroid + s.shift) : s.centroid,
                                positions[v], normals[v]);
    }
  };
  if (pool) {
    pool->parallelFor(m_planes.size(), kMinPlanesPerThread, orient);
  } else {
    orient(0, m_planes.size());
  }
}

std::vector<float> IncrementalPlaneFitter::toleranceMmPerRad() const {
  std::vector<float> t(m_solved.size());
  for (std::size_t v = 0; v < t.size(); ++v)
    t[v] = m_solved[v].tolerancePerRad;
  return t;
}

void IncrementalPlaneFitter::snapshotFromFitted() {
  // In exact mode every plane's moments are those of the folded positions m_fitted.
  m_snapshot.resize(m_hoods.indices.size());
  for (std::size_t k = 0; k < m_snapshot.size(); ++k)
    m_snapshot[k] = m_fitted[m_hoods.indices[k]];
}

RefitStats IncrementalPlaneFitter::update(std::span<const Float3> positions, std::span<const Float3> normals,
                                          float toleranceMm) {
  if (m_tolerantMode) {  // the moments follow per-plane snapshots: start the exact mode afresh
    fitAll(positions, normals);
    return {positions.size(), m_hoods.vertexCount()};
  }
  std::vector<std::uint32_t> moved;
  const float tol2 = toleranceMm * toleranceMm;
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    const Float3 d = positions[v] - m_fitted[v];
    if (dot(d, d) > tol2) moved.push_back(v);
  }
  return updateMoved(positions, normals, moved);
}

RefitStats IncrementalPlaneFitter::update(std::span<const Float3> positions, std::span<const Float3> normals,
                                          const PlaneRefitSettings& refit, WorkerPool* pool) {
  if (!(refit.maxNormalErrorRad > 0.0)) return update(positions, normals, 0.0f);
  if (!m_tolerantMode) {
    snapshotFromFitted();
    m_tolerantMode = true;
  }
  RefitStats stats;
  // m_fitted: the positions of the previous update; a plane none of whose members changed
  // since then keeps its state (shift included).
  m_changed.assign(positions.size(), 0);
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (!(positions[v] == m_fitted[v])) ++stats.movedVertices, m_fitted[v] = positions[v], m_changed[v] = 1;
  const double theta = refit.maxNormalErrorRad;
  const auto quantised =
      stats.movedVertices ? quantiseAll(positions, m_origin) : std::vector<detail::FixedPoint>{};
  std::atomic<std::size_t> refitted{0};
  // Planes are independent (each reads positions, writes only its own state), so they split
  // over the pool; the result does not depend on the number of threads.
  const auto planes = [&](std::size_t b, std::size_t e) {
    std::size_t count = 0;
    for (auto j = std::uint32_t(b); j < e; ++j)
      count += refitPlaneWithin(j, positions, quantised, theta) ? 1 : 0;
    refitted += count;
  };
  if (pool && stats.movedVertices) {
    pool->parallelFor(m_hoods.vertexCount(), kMinPlanesPerThread, planes);
  } else if (stats.movedVertices) {
    planes(0, m_hoods.vertexCount());
  }
  stats.refittedPlanes = refitted.load();
  orientPlanes(positions, normals, pool);
  return stats;
}

bool IncrementalPlaneFitter::refitPlaneWithin(std::uint32_t j, std::span<const Float3> positions,
                                              std::span<const detail::FixedPoint> quantised, double theta) {
  const auto first = m_hoods.offsets[j], last = m_hoods.offsets[j + 1];
  bool changed = false;
  for (auto k = first; k < last && !changed; ++k)
    changed = m_changed[m_hoods.indices[k]] != 0;
  if (!changed) return false;  // nothing moved since the previous update: keep the state, shift too
  // The members' displacements since the plane's last solve: their mean moves the centroid,
  // their centred RMS rho can turn the normal by up to rho K_j (header). Taken relative to the
  // first member's so that a large common translation cancels before the float sums.
  const Float3 base = positions[m_hoods.indices[first]] - m_snapshot[first];
  Float3 sum{0.0f, 0.0f, 0.0f};
  float sum2 = 0.0f;
  for (auto k = first + 1; k < last; ++k) {
    const Float3 e = (positions[m_hoods.indices[k]] - m_snapshot[k]) - base;
    sum = sum + e, sum2 += dot(e, e);
  }
  const float n = float(last - first);
  const Float3 mean = {sum.x / n, sum.y / n, sum.z / n};
  const double rho = std::sqrt(std::max(double(sum2) / double(n) - double(dot(mean, mean)), 0.0));
  Solved& s = m_solved[j];
  if (rho > theta * double(s.tolerancePerRad) - kQuantisationSlackMm) {
    solvePlaneFromScratch(j, positions, quantised);
    return true;
  }
  s.shift = {double(base.x) + double(mean.x), double(base.y) + double(mean.y),
             double(base.z) + double(mean.z)};
  return false;
}

RefitStats IncrementalPlaneFitter::updateMoved(std::span<const Float3> positions,
                                               std::span<const Float3> normals,
                                               std::span<const std::uint32_t> movedVertices) {
  if (m_tolerantMode) {
    fitAll(positions, normals);
    return {movedVertices.size(), m_hoods.vertexCount()};
  }
  const RefitStats stats = foldAndSolve(positions, normals, movedVertices);
  if (stats.refittedPlanes != m_hoods.vertexCount()) orientPlanes(positions, normals);
  return stats;
}

RefitStats IncrementalPlaneFitter::foldAndSolve(std::span<const Float3> positions,
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
  // Step 2: only the dirty planes solve their eigenproblem again (orientation and offset follow
  // for every plane in the caller).
  for (auto j : m_dirtyList)
    solvePlane(j);
  return {movedVertices.size(), m_dirtyList.size()};
}

}  // namespace tissue::mesh
