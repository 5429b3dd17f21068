#include "tissue/mesh/tangent_frames.h"

#include <cmath>
#include <vector>

#include "tissue/mesh/worker_pool.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

constexpr std::size_t kMinGroupsPerThread = 2048;

/// Angle-weighted sums of the unit UV gradients of the triangles around render vertex i.
void gatherGradients(std::span<const TriangleGeometry> geometry, const VertexCorners& corners,
                     std::uint32_t i, Float3& du, Float3& dv) {
  du = dv = Float3{};
  for (std::uint32_t j = corners.offsets[i]; j < corners.offsets[i + 1]; ++j) {
    const std::uint32_t c = corners.corners[j];
    const TriangleGeometry& g = geometry[c / 3];
    const float w = g.angles[c % 3];
    du = du + g.dPdu * w;
    dv = dv + g.dPdv * w;
  }
}

/// Gram-Schmidt of the u direction against the normal; handedness from the v direction's side.
Float4 orthonormalFrame(Float3 n, Float3 du, Float3 dv) {
  Float3 t = du - n * dot(n, du);
  if (length(t) < 1e-12f) {
    // No usable u direction (no UV area around the vertex): any unit vector orthogonal to n.
    const Float3 axis = std::abs(n.x) < 0.9f ? Float3{1, 0, 0} : Float3{0, 1, 0};
    t = axis - n * dot(n, axis);
  }
  t = normalizeOr(t, Float3{1, 0, 0});
  const float w = dot(cross(n, t), dv) < 0.0f ? -1.0f : 1.0f;
  return {t.x, t.y, t.z, w};
}

/// Frames of one seam group of k > 1 copies. Copies a, b are "alike" when their accumulated u
/// and v directions agree within 45 degrees (so the handedness agrees too); each copy gets the
/// sum, in ascending copy order, of its own gradients and those of the copies alike to it.
/// `scratch` is reused across groups (4 k entries).
void poolSeamGroup(std::span<const TriangleGeometry> geometry, const TangentTopology& topology,
                   std::span<const Float3> normals, std::span<const std::uint32_t> group,
                   std::vector<Float3>& scratch, std::span<Float4> tangents) {
  const std::size_t k = group.size();
  scratch.resize(4 * k);
  Float3* du = scratch.data();
  Float3* dv = du + k;
  Float3* unitU = dv + k;
  Float3* unitV = unitU + k;
  for (std::size_t a = 0; a < k; ++a) {
    gatherGradients(geometry, topology.corners, group[a], du[a], dv[a]);
    unitU[a] = normalizeOr(du[a], Float3{});
    unitV[a] = normalizeOr(dv[a], Float3{});
  }
  const float cos45 = std::sqrt(0.5f);
  for (std::size_t a = 0; a < k; ++a) {
    Float3 pooledU{}, pooledV{};
    for (std::size_t b = 0; b < k; ++b)
      if (a == b || (dot(unitU[a], unitU[b]) > cos45 && dot(unitV[a], unitV[b]) > cos45)) {
        pooledU = pooledU + du[b];
        pooledV = pooledV + dv[b];
      }
    tangents[group[a]] = orthonormalFrame(normals[group[a]], pooledU, pooledV);
  }
}

}  // namespace

void computeTangentFrames(std::span<const Float3> positions, std::span<const Float2> uvs,
                          std::span<const Triangle> triangles, std::span<const Float3> normals,
                          std::span<Float4> tangents, std::span<const std::uint32_t> geometricIndex) {
  const TangentTopology topology = buildTangentTopology(uvs, triangles, geometricIndex);
  std::vector<TriangleGeometry> geometry(triangles.size());
  computeTriangleGeometry(positions, triangles, topology.uvBases, 0, triangles.size(), geometry);
  computeTangentFrames(geometry, topology, normals, tangents);
}

void computeTangentFramesOfGroups(std::span<const TriangleGeometry> geometry, const TangentTopology& topology,
                                  std::span<const Float3> normals, std::size_t firstGroup,
                                  std::size_t lastGroup, std::span<Float4> tangents) {
  // Step 1: accumulate each triangle's unit UV gradients (Lengyel 2001) at its corners,
  // weighted by the corner angle so the result does not depend on triangulation.
  // Step 2: pool the gradients of seam copies whose charts are oriented alike.
  // Step 3: Gram-Schmidt against the normal.
  std::vector<Float3> scratch;
  const std::uint32_t* offsets = topology.copyOffsets.data();
  for (std::size_t g = firstGroup; g < lastGroup; ++g) {
    const std::span<const std::uint32_t> group(topology.copies.data() + offsets[g],
                                               offsets[g + 1] - offsets[g]);
    if (group.size() == 1) {
      Float3 du, dv;
      gatherGradients(geometry, topology.corners, group[0], du, dv);
      tangents[group[0]] = orthonormalFrame(normals[group[0]], du, dv);
    } else if (group.size() > 1) {
      poolSeamGroup(geometry, topology, normals, group, scratch, tangents);
    }
  }
}

void computeTangentFrames(std::span<const TriangleGeometry> geometry, const TangentTopology& topology,
                          std::span<const Float3> normals, std::span<Float4> tangents, WorkerPool* pool) {
  parallelFor(pool, topology.groupCount(), kMinGroupsPerThread, [&](std::size_t b, std::size_t e) {
    computeTangentFramesOfGroups(geometry, topology, normals, b, e, tangents);
  });
}

}  // namespace tissue::mesh
