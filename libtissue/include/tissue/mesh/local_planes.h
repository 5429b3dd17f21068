#pragma once
/// \file
/// The per-vertex local planes of subsurface texture mapping (François et al. §2.2):
/// for each vertex V a least-squares plane through the vertices inside a sphere of radius
/// r = -log(eps) / sigma_t (eq. 7-8), stored as its unit normal N_S and the offset d along the
/// vertex normal N_V at which the plane crosses it, P_V = V + d N_V (eq. 14). The renderer
/// interpolates (N_S, d) across triangles (eq. 9).
///
/// Neighbourhoods are taken in the rest state and kept under deformation (see
/// docs/DECISIONS.md): they follow the material, so a plane changes continuously in time and
/// re-fitting after a deformation only touches planes whose neighbourhood contains a vertex
/// that moved. A change of topology (a cut or a tear) needs new neighbourhoods: construct a new
/// IncrementalPlaneFitter on the new mesh.

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::mesh {

class WorkerPool;

namespace detail {
struct FixedPoint;  // a quantised position, libtissue/src/mesh/fixed_moments.h
}  // namespace detail

/// Parameters of the neighbourhood sphere (François eq. 7-8).
struct PlaneFitSettings {
  float sigma_t = 1.5f;   ///< mm^-1, extinction of the first layer (smallest RGB channel)
  float epsilon = 0.01f;  ///< light attenuated below this fraction is ignored (unitless, 0..1)

  /// r = -log(eps) / sigma_t (eq. 8), mm.
  float radiusMm() const { return -std::log(epsilon) / sigma_t; }
};

/// Compressed neighbourhood lists: vertex i's neighbours are indices[offsets[i] .. offsets[i+1]).
/// Every list contains i itself and its 1-ring (so a mesh coarser than the sphere still gets a
/// plane, and a plane is re-fitted whenever its vertex normal can have changed). The relation
/// is symmetric.
struct Neighbourhoods {
  std::vector<std::uint32_t> offsets;  ///< #V + 1
  std::vector<std::uint32_t> indices;  ///< neighbour vertex indices
  std::size_t vertexCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

/// Finds, for every vertex, the vertices within `radiusMm` of it (uniform grid, O(V k)),
/// plus its 1-ring when `oneRingOf` is non-empty (triangles indexing the same vertices).
Neighbourhoods findNeighbourhoods(std::span<const Float3> positions, float radiusMm,
                                  std::span<const Triangle> oneRingOf = {});

/// Fits every vertex's plane from scratch (the reference the incremental fitter must equal).
/// \param positions  #V current positions, mm
/// \param normals    #V current unit vertex normals (orient N_S and define d, eq. 14)
/// \param hoods      neighbourhoods from findNeighbourhoods
/// \param planes     #V output (N_S.xyz, d in mm)
void fitVertexPlanes(std::span<const Float3> positions, std::span<const Float3> normals,
                     const Neighbourhoods& hoods, std::span<Float4> planes);

/// How far two sets of planes are apart.
struct PlaneDeviation {
  double maxAngleRad = 0.0;  ///< largest angle between corresponding normals, rad (atan2 form: exact near 0)
  double maxOffsetMm = 0.0;  ///< largest difference of the offsets d, mm
};

/// Compares two #V plane arrays (N_S, d).
PlaneDeviation comparePlanes(std::span<const Float4> a, std::span<const Float4> b);

/// How closely the incremental re-fit follows the current positions (issue 11).
///
/// Under a simulator every vertex moves a little every frame, mostly along with its
/// neighbours: a plane needs solving again only when its neighbourhood changed shape enough to
/// turn its normal, not when it was carried along. Each plane keeps the positions it was last
/// solved at and solves again only when the RMS of its members' displacements since then, less
/// their mean (a translation turns no plane), exceeds a tolerance tau_j derived from its own
/// covariance (see IncrementalPlaneFitter); then N_S stays within `maxNormalErrorRad` of a full
/// re-fit of the current positions. Orientation and offset d (eq. 14) are recomputed every update
/// from the current vertex, its normal and the centroid moved by that mean, so d only inherits
/// the plane's tilt: |d - d_full| <~ r theta / (N_S . N_V) (r: the sphere radius).
struct PlaneRefitSettings {
  /// rad: the largest angle between an incrementally re-fitted normal N_S and the full re-fit's.
  /// 1e-4 rad tilts a plane by 0.3 um across the 3 mm sphere of the liver's first layer, far
  /// below the mesh's resolution and what the renderer can show (half-float radiance, 8-bit
  /// output); 0 re-solves every plane any of whose vertices moved: bit-identical to a full re-fit.
  double maxNormalErrorRad = 1e-4;
};

/// Statistics of one incremental update.
struct RefitStats {
  std::size_t movedVertices = 0;   ///< vertices whose position changed beyond the tolerance
  std::size_t refittedPlanes = 0;  ///< planes whose neighbourhood contained a moved vertex
};

/// Keeps the planes of a deforming mesh up to date, re-fitting only where it moved.
///
/// Per vertex it keeps the position last folded into the moments; per plane it keeps the first and second
/// moments of its neighbourhood in exact fixed-point integers (positions quantised to 2^-20 mm about the
/// rest-state box centre). A moved vertex adds the difference of its new and old moments to every plane that
/// contains it, and only those planes solve their 3x3 eigenproblem again. Integer sums are exact and
/// associative, so the incremental moments equal a from-scratch sum bit for bit, after any number of frames:
/// an incremental re-fit gives exactly the planes of a full re-fit (fitVertexPlanes) of the
/// folded positions. Orientation and offset d are recomputed for every plane on every update
/// from the current vertex and its normal (cheap next to the eigenproblem).
///
/// The tolerant update (PlaneRefitSettings) keeps per plane the positions of its members at its
/// last solve, s_i, and the moments of those, and bounds the angle to a full re-fit of the
/// current positions p_i. With the solved covariance C (eigenvalues l1 <= l2 <= l3, eigenvectors
/// e_k) and the current one C + E, the normal turns by theta ~ sqrt(sum_k (e_k.E e1)^2 /
/// (lk - l1)^2), k = 2, 3 (first-order eigenvector perturbation). With the centred displacements
/// u_i = (p_i - s_i) - mean(p - s) of RMS rho, E = mean(u q^T + q u^T) + O(rho^2) (q_i = s_i - c),
/// and Cauchy-Schwarz gives |e_k.E e1| <= rho sqrt(l1 + lk); hence theta <= rho K_j with
/// K_j = sqrt(sum_k (l1 + lk) / (lk - l1)^2), and the plane solves again once rho > theta_max / K_j
/// (about theta_max r / (2 sqrt 2) for a flat disc of radius r: 0.11 um at r = 3 mm). Solving
/// sums the plane's moments from scratch, exactly as fitAll does.
class IncrementalPlaneFitter {
 public:
  /// \param restPositions  #V positions that define the neighbourhoods, mm
  /// \param triangles      topology (for the 1-ring)
  IncrementalPlaneFitter(std::span<const Float3> restPositions, std::span<const Triangle> triangles,
                         const PlaneFitSettings& settings = {});
  ~IncrementalPlaneFitter();
  IncrementalPlaneFitter(IncrementalPlaneFitter&&) noexcept;
  IncrementalPlaneFitter& operator=(IncrementalPlaneFitter&&) noexcept;

  /// Full re-fit at `positions`: every plane's moments summed from scratch and solved.
  void fitAll(std::span<const Float3> positions, std::span<const Float3> normals);

  /// Incremental re-fit: vertices that moved by more than `toleranceMm` since the last fit
  /// update their planes' moments; only those planes are solved again. With a tolerance of 0
  /// the result equals fitAll exactly.
  RefitStats update(std::span<const Float3> positions, std::span<const Float3> normals,
                    float toleranceMm = 0.0f);

  /// Tolerant re-fit (see PlaneRefitSettings): afterwards every normal N_S is within
  /// `refit.maxNormalErrorRad` of a full re-fit of `positions` (to first order in the angle).
  /// A bound of 0 is update(positions, normals, 0.0f).
  /// \param pool  splits the planes over its threads (nullptr: the caller's only); the result
  ///              does not depend on it
  RefitStats update(std::span<const Float3> positions, std::span<const Float3> normals,
                    const PlaneRefitSettings& refit, WorkerPool* pool = nullptr);

  /// Incremental re-fit when the caller knows which vertices moved.
  RefitStats updateMoved(std::span<const Float3> positions, std::span<const Float3> normals,
                         std::span<const std::uint32_t> movedVertices);

  std::span<const Float4> planes() const { return m_planes; }
  /// Per plane, 1 / K_j (mm/rad): the RMS centred displacement (mm) it tolerates per radian of
  /// normal error (scale by PlaneRefitSettings::maxNormalErrorRad).
  std::vector<float> toleranceMmPerRad() const;
  const Neighbourhoods& neighbourhoods() const { return m_hoods; }
  const PlaneFitSettings& settings() const { return m_settings; }

 private:
  struct Moments;  // fixed-point sums, defined in local_planes.cpp
  struct Solved;   // a plane's unoriented normal, centroid and tolerance, defined there too
  RefitStats foldAndSolve(std::span<const Float3> positions, std::span<const Float3> normals,
                          std::span<const std::uint32_t> movedVertices);
  void solvePlane(std::uint32_t v);
  void orientPlanes(std::span<const Float3> positions, std::span<const Float3> normals,
                    WorkerPool* pool = nullptr);
  bool refitPlaneWithin(std::uint32_t j, std::span<const Float3> positions,
                        std::span<const detail::FixedPoint> quantised, double theta);
  void solvePlaneFromScratch(std::uint32_t v, std::span<const Float3> positions,
                             std::span<const detail::FixedPoint> quantised);
  void snapshotFromFitted();

  PlaneFitSettings m_settings;
  Neighbourhoods m_hoods;
  Float3 m_origin;                 // quantisation origin: rest-state bounding-box centre, mm
  std::vector<Moments> m_moments;  // per plane
  std::vector<Solved> m_solved;    // per plane: the eigenproblem's answer before orientation
  // Tolerant mode: per neighbourhood entry (as m_hoods.indices), the member's position at its
  // plane's last solve; per plane the mean displacement since (moves the centroid, mm).
  std::vector<Float3> m_snapshot;
  std::vector<char> m_changed;   // per vertex, this update: moved since the previous one
  bool m_tolerantMode = false;   // m_snapshot, not m_fitted, describes the moments
  std::vector<Float3> m_fitted;  // positions at the last fit, per vertex
  std::vector<Float4> m_planes;  // per vertex (N_S, d)
  std::vector<std::uint32_t> m_dirtyStamp;
  std::uint32_t m_stamp = 0;
  std::vector<std::uint32_t> m_dirtyList;
};

}  // namespace tissue::mesh
