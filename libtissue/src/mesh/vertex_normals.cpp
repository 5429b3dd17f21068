#include "tissue/mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

void computeVertexNormals(std::span<const Float3> positions, std::span<const Triangle> triangles,
                          std::span<Float3> normals) {
  std::fill(normals.begin(), normals.end(), Float3{0.0f, 0.0f, 0.0f});
  for (const auto& tri : triangles) {
    const Float3 p[3] = {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
    const Float3 n = normalizeOr(cross(p[1] - p[0], p[2] - p[0]), Float3{});
    for (int k = 0; k < 3; ++k) {
      // Interior angle at corner k: the weight of Thürmer and Wüthrich (1998).
      const Float3 e1 = normalizeOr(p[(k + 1) % 3] - p[k], Float3{});
      const Float3 e2 = normalizeOr(p[(k + 2) % 3] - p[k], Float3{});
      const float angle = std::acos(std::clamp(dot(e1, e2), -1.0f, 1.0f));
      Float3& out = normals[tri[k]];
      out = out + n * angle;
    }
  }
  for (auto& n : normals)
    n = normalizeOr(n, Float3{0.0f, 0.0f, 1.0f});
}

}  // namespace tissue::mesh
