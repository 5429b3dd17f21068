// The ray-mesh interface: mesh checks, the BVH back end, and the choice of back end.
#include "tissue/truth/ray_mesh.h"

#include <cmath>
#include <string>

#include "depth_tree.h"
#include "embree_mesh.h"
#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::truth {
namespace {

class BvhMesh final : public RayMesh {
 public:
  BvhMesh(std::span<const Float3> positions, std::span<const Triangle> triangles)
      : m_bvh(positions, triangles), m_depth(positions, triangles) {}
  std::optional<MeshHit> intersect(const std::array<double, 3>& o, const std::array<double, 3>& d,
                                   double tMin, double tMax) const override {
    const auto hit = m_bvh.intersect(o, d, tMin, tMax);
    if (!hit) return std::nullopt;
    return MeshHit{hit->t, hit->triangle, hit->b1, hit->b2};
  }
  std::optional<SurfacePoint> nearest(const std::array<double, 3>& p, double maxDistanceMm) const override {
    return m_depth.nearest({p[0], p[1], p[2]}, maxDistanceMm);
  }
  Intersector kind() const override { return Intersector::Bvh; }

 private:
  subsurface::TriangleBvh m_bvh;
  detail::DepthTree m_depth;
};

}  // namespace

const char* intersectorName(Intersector intersector) {
  switch (intersector) {
    case Intersector::Embree:
      return "embree";
    case Intersector::Bvh:
      return "bvh";
    case Intersector::Best:
      return "best";
  }
  return "unknown";
}

bool embreeAvailable() {
  return detail::embreeBuiltIn();
}

Result<std::unique_ptr<RayMesh>> makeRayMesh(std::span<const Float3> positions,
                                             std::span<const Triangle> triangles, Intersector intersector) {
  if (positions.empty() || triangles.empty())
    return Error{"ray mesh: the mesh is empty (" + std::to_string(positions.size()) + " vertices, " +
                 std::to_string(triangles.size()) + " triangles); give a closed triangle mesh"};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Float3 p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return Error{"ray mesh: vertex " + std::to_string(i) + " has a non-finite position"};
  }
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::uint32_t v : triangles[i])
      if (v >= positions.size())
        return Error{"ray mesh: triangle " + std::to_string(i) + " names vertex " + std::to_string(v) +
                     " of " + std::to_string(positions.size())};
  if (intersector == Intersector::Embree || (intersector == Intersector::Best && detail::embreeBuiltIn()))
    return detail::makeEmbreeMesh(positions, triangles);
  return std::unique_ptr<RayMesh>(new BvhMesh(positions, triangles));
}

}  // namespace tissue::truth
