#pragma once
/// \file
/// What shading needs of a deforming surface, kept in step every frame: render-vertex
/// positions, angle-weighted normals, UV tangent frames and the local planes of subsurface
/// texture mapping, the planes re-fitted only where the mesh moved.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/mesh/shading_topology.h"
#include "tissue/mesh/triangle_geometry.h"

namespace tissue::mesh {

class WorkerPool;

/// Wall-clock cost of one update, per phase (ms), and what the plane re-fit touched.
struct SurfaceUpdateStats {
  double gatherMs = 0.0;
  double normalsMs = 0.0;
  double tangentsMs = 0.0;
  double planesMs = 0.0;
  RefitStats refit;
  bool planes = false;    ///< the planes were re-fitted (SurfaceWork::planes)
  bool tangents = false;  ///< the tangent frames were computed (SurfaceWork::tangents)
};

/// Which of the shading attributes the updates keep current; normals always are (every method
/// reads them, and the planes and tangents are built on them). A renderer that shades without
/// the local planes (all but the ray march) or without tangents (no normal map, neither the ray
/// march nor parallax) need not pay for them (issue 16).
struct SurfaceWork {
  bool planes = true;    ///< the local planes' incremental re-fit
  bool tangents = true;  ///< the tangent frames
};

/// A surface mesh whose shading attributes follow its deformation.
///
/// The simulator moves geometric vertices (one per surface point); the renderer draws render
/// vertices (split at UV seams). Normals and planes are computed per geometric vertex so they
/// are continuous across seams; tangents per render vertex, from each chart's own UVs.
///
/// Everything that does not change while the surface deforms (vertex -> corner lists, UV
/// constants, seam groups) is built once in create(); each update computes the triangles'
/// shading geometry once and gathers it per vertex on a small worker pool. Results do not
/// depend on the number of threads, and equal computeVertexNormals / computeTangentFrames.
class DeformableSurface {
 public:
  /// Validates `mesh` and computes everything at the rest state. Fails when the mesh is
  /// invalid or has no UVs (tangent frames need them).
  /// \param threadCount  threads for the per-frame update, the caller's included; 0 picks the
  ///                     hardware's concurrency
  /// \param refit        how closely the incremental planes follow (default: normals within
  ///                     1e-4 rad of a full re-fit; {.maxNormalErrorRad = 0}: exact)
  static Result<DeformableSurface> create(SurfaceMesh mesh, const PlaneFitSettings& planeSettings = {},
                                          unsigned threadCount = 0, const PlaneRefitSettings& refit = {});

  ~DeformableSurface();
  DeformableSurface(DeformableSurface&&) noexcept;
  DeformableSurface& operator=(DeformableSurface&&) noexcept;

  /// Moves the surface: `geometricPositions` holds one position (mm) per geometric vertex.
  /// Normals and tangents are recomputed exactly; the planes follow within planeRefit()'s
  /// bound (a vertex whose motion could not turn a plane normal by that much keeps its planes).
  SurfaceUpdateStats update(std::span<const Float3> geometricPositions);
  /// As update(positions), but vertices that moved less than `toleranceMm` (mm, one for all)
  /// keep their planes; 0 is exact. No bound on the normals' error follows from it.
  SurfaceUpdateStats update(std::span<const Float3> geometricPositions, float toleranceMm);

  /// What the next updates keep current. An attribute switched off goes stale: planes() or
  /// tangents() keep the values of its last computation. Switching one on brings it up to date
  /// at once, before anything reads it: the incremental re-fit over every vertex that moved
  /// since the planes' last fit (what a surface that re-fitted every frame holds: exactly with
  /// maxNormalErrorRad = 0, else both within planeRefit()'s bound of a full re-fit), the
  /// tangents from the current normals (exactly). Returns what it brought up to date (to upload).
  SurfaceWork setWork(const SurfaceWork& work);
  const SurfaceWork& work() const { return m_work; }
  /// Whether planes() and tangents() describe the current positions.
  bool planesCurrent() const { return m_planesCurrent; }
  bool tangentsCurrent() const { return m_tangentsCurrent; }

  /// How closely the incremental planes follow the positions (for the next updates).
  void setPlaneRefit(const PlaneRefitSettings& refit) { m_refit = refit; }
  const PlaneRefitSettings& planeRefit() const { return m_refit; }

  /// Re-fits every plane from scratch (the reference for the incremental path).
  void refitAllPlanes();

  // Render-vertex arrays, ready to upload.
  std::span<const Float3> positions() const { return m_mesh.positions; }  ///< mm
  std::span<const Float2> uvs() const { return m_mesh.uvs; }
  std::span<const Triangle> triangles() const { return m_mesh.triangles; }
  std::span<const Float3> normals() const { return m_normals; }    ///< unit
  std::span<const Float4> tangents() const { return m_tangents; }  ///< (T, handedness)
  std::span<const Float4> planes() const { return m_planes; }      ///< (N_S, d mm), eq. 14

  // Geometric-vertex arrays (the simulator's view).
  std::span<const Float3> geometricRestPositions() const { return m_geoRest; }
  std::span<const Float3> geometricPositions() const { return m_geoPositions; }
  std::span<const Triangle> geometricTriangles() const { return m_geoTriangles; }
  /// Geometric vertices on open boundaries (a patch's pinnable border).
  std::span<const std::uint32_t> boundaryVertices() const { return m_boundary; }

  const SurfaceMesh& mesh() const { return m_mesh; }
  const IncrementalPlaneFitter& planeFitter() const { return m_fitter; }
  /// Threads the update runs on, the caller's included.
  unsigned threadCount() const;

 private:
  DeformableSurface(SurfaceMesh mesh, std::vector<Float3> geoRest, std::vector<Triangle> geoTriangles,
                    const PlaneFitSettings& settings, unsigned threadCount, const PlaneRefitSettings& refit);
  template <class Refit>
  SurfaceUpdateStats updateWith(std::span<const Float3> geometricPositions, const Refit& refit);
  void computeNormals();
  void computeTangents();
  void copyPlanes();
  void refitPlanes();  ///< the incremental re-fit at the current positions (setWork's catch-up)

  SurfaceMesh m_mesh;
  std::vector<Float3> m_geoRest;
  std::vector<Float3> m_geoPositions;
  std::vector<Triangle> m_geoTriangles;
  std::vector<std::uint32_t> m_boundary;
  std::vector<Float3> m_geoNormals;
  IncrementalPlaneFitter m_fitter;
  PlaneRefitSettings m_refit;
  SurfaceWork m_work;
  bool m_planesCurrent = true, m_tangentsCurrent = true;
  std::vector<Float3> m_normals;
  std::vector<Float4> m_tangents;
  std::vector<Float4> m_planes;
  // Per-frame-invariant topology and per-frame scratch of the shading update.
  VertexCorners m_geoCorners;
  TangentTopology m_tangentTopology;
  std::vector<TriangleGeometry> m_triangleGeometry;
  std::unique_ptr<WorkerPool> m_pool;
};

/// Geometric positions (one per geometric vertex) of a render mesh.
std::vector<Float3> geometricPositionsOf(const SurfaceMesh& mesh);
/// The triangles re-indexed to geometric vertices.
std::vector<Triangle> geometricTrianglesOf(const SurfaceMesh& mesh);

}  // namespace tissue::mesh
