#pragma once
/// \file
/// Nearest-hit ray queries and nearest-point queries on a triangle mesh behind one small interface, with two
/// back ends: Embree 3 (Intel's ray-tracing kernels, single precision; built in when CMake finds Debian's
/// libembree-dev) and the project's own double-precision BVH (tissue/subsurface/triangle_bvh.h).
/// Both answer the same query; docs/DECISIONS.md ("The path-traced truth") gives the measured
/// rates. Positions in mm. Queries are const and safe from many threads at once.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::truth {

/// Which ray-mesh back end.
enum class Intersector {
  Embree,  ///< Embree 3 (an Error from makeRayMesh when tissue was built without it)
  Bvh,     ///< tissue::subsurface::TriangleBvh
  Best,    ///< Embree where built in, else the BVH
};

/// "embree", "bvh" or "best".
const char* intersectorName(Intersector intersector);

/// Whether this build has the Embree back end.
bool embreeAvailable();

/// Where a ray met the mesh.
struct MeshHit {
  double t = 0.0;              ///< distance along the unit direction, mm
  std::uint32_t triangle = 0;  ///< index into the triangle array
  double b1 = 0.0;             ///< barycentric weight of the triangle's second vertex
  double b2 = 0.0;             ///< barycentric weight of the third vertex
};

/// The surface point nearest to a query point.
struct SurfacePoint {
  double distanceMm = 0.0;     ///< mm
  std::uint32_t triangle = 0;  ///< index into the triangle array
  double b1 = 0.0;             ///< barycentric weight of the triangle's second vertex
  double b2 = 0.0;             ///< barycentric weight of the third vertex
};

/// A mesh that answers nearest-hit and nearest-point queries. Immutable after construction.
class RayMesh {
 public:
  virtual ~RayMesh() = default;
  /// The nearest hit with t in (tMin, tMax) along origin + t dir (`dir` unit, mm), or none.
  virtual std::optional<MeshHit> intersect(const std::array<double, 3>& origin,
                                           const std::array<double, 3>& dir, double tMin,
                                           double tMax) const = 0;
  /// The surface point nearest to `point` (mm) within `maxDistanceMm`, or none (the bound prunes
  /// the search). Embree: rtcPointQuery; the BVH back end: its own hierarchy (Ericson 2005).
  virtual std::optional<SurfacePoint> nearest(const std::array<double, 3>& point,
                                              double maxDistanceMm) const = 0;
  /// The back end that answers (never Best).
  virtual Intersector kind() const = 0;
};

/// Builds the back end `intersector` over the mesh (copied). Errors: an empty mesh, an index out of
/// range, a non-finite position, Embree asked for but not built in, or Embree failing.
Result<std::unique_ptr<RayMesh>> makeRayMesh(std::span<const Float3> positions,
                                             std::span<const Triangle> triangles,
                                             Intersector intersector = Intersector::Best);

}  // namespace tissue::truth
