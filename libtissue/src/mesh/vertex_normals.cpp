#include "tissue/mesh/vertex_normals.h"

#include <vector>

#include "tissue/mesh/worker_pool.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {
constexpr std::size_t kMinVerticesPerThread = 2048;
}  // namespace

void computeVertexNormals(std::span<const Float3> positions, std::span<const Triangle> triangles,
                          std::span<Float3> normals) {
  std::vector<TriangleGeometry> geometry(triangles.size());
  computeTriangleGeometry(positions, triangles, {}, 0, triangles.size(), geometry);
  computeVertexNormals(geometry, buildVertexCorners(triangles, normals.size()), normals);
}

void gatherVertexNormals(std::span<const TriangleGeometry> geometry, const VertexCorners& corners,
                         std::size_t first, std::size_t last, std::span<Float3> normals) {
  const std::uint32_t* offsets = corners.offsets.data();
  const std::uint32_t* list = corners.corners.data();
  for (std::size_t v = first; v < last; ++v) {
    Float3 sum{};
    for (std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i) {
      const std::uint32_t c = list[i];
      const TriangleGeometry& g = geometry[c / 3];
      sum = sum + g.normal * g.angles[c % 3];
    }
    normals[v] = normalizeOr(sum, Float3{0.0f, 0.0f, 1.0f});
  }
}

void computeVertexNormals(std::span<const TriangleGeometry> geometry, const VertexCorners& corners,
                          std::span<Float3> normals, WorkerPool* pool) {
  parallelFor(pool, normals.size(), kMinVerticesPerThread,
              [&](std::size_t b, std::size_t e) { gatherVertexNormals(geometry, corners, b, e, normals); });
}

}  // namespace tissue::mesh
