#include "tissue/mesh/tangent_frames.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

/// Seam copies i, j of one geometric vertex are "alike" when their accumulated u and v
/// directions agree within 45 degrees (so the handedness agrees too); alike copies get the
/// sum of their gradients.
void poolAlikeSeamCopies(std::span<const std::uint32_t> geometricIndex, std::vector<Float3>& du,
                         std::vector<Float3>& dv) {
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> copies;
  for (std::uint32_t i = 0; i < geometricIndex.size(); ++i)
    copies[geometricIndex[i]].push_back(i);
  const float cos45 = std::sqrt(0.5f);
  const auto alike = [&](std::uint32_t a, std::uint32_t b) {
    const Float3 ua = normalizeOr(du[a], Float3{}), ub = normalizeOr(du[b], Float3{});
    const Float3 va = normalizeOr(dv[a], Float3{}), vb = normalizeOr(dv[b], Float3{});
    return dot(ua, ub) > cos45 && dot(va, vb) > cos45;
  };
  std::vector<Float3> pooledU, pooledV;
  for (auto& [geo, list] : copies) {
    if (list.size() < 2) continue;
    pooledU.assign(list.size(), Float3{});
    pooledV.assign(list.size(), Float3{});
    for (std::size_t a = 0; a < list.size(); ++a)
      for (std::size_t b = 0; b < list.size(); ++b)
        if (a == b || alike(list[a], list[b])) {
          pooledU[a] = pooledU[a] + du[list[b]];
          pooledV[a] = pooledV[a] + dv[list[b]];
        }
    for (std::size_t a = 0; a < list.size(); ++a) {
      du[list[a]] = pooledU[a];
      dv[list[a]] = pooledV[a];
    }
  }
}

}  // namespace

void computeTangentFrames(std::span<const Float3> positions, std::span<const Float2> uvs,
                          std::span<const Triangle> triangles, std::span<const Float3> normals,
                          std::span<Float4> tangents, std::span<const std::uint32_t> geometricIndex) {
  // Step 1: accumulate each triangle's UV gradients dP/du and dP/dv (Lengyel 2001) at its
  // corners, weighted by the corner angle so the result does not depend on triangulation.
  std::vector<Float3> du(positions.size()), dv(positions.size());
  for (const auto& tri : triangles) {
    const Float3 e1 = positions[tri[1]] - positions[tri[0]];
    const Float3 e2 = positions[tri[2]] - positions[tri[0]];
    const float s1 = uvs[tri[1]].x - uvs[tri[0]].x, t1 = uvs[tri[1]].y - uvs[tri[0]].y;
    const float s2 = uvs[tri[2]].x - uvs[tri[0]].x, t2 = uvs[tri[2]].y - uvs[tri[0]].y;
    const float det = s1 * t2 - s2 * t1;
    if (std::abs(det) < 1e-20f) continue;  // no UV area: no gradient information
    const float r = 1.0f / det;
    const Float3 gu = (e1 * t2 - e2 * t1) * r;  // dP/du
    const Float3 gv = (e2 * s1 - e1 * s2) * r;  // dP/dv
    for (int k = 0; k < 3; ++k) {
      const Float3 a = normalizeOr(positions[tri[(k + 1) % 3]] - positions[tri[k]], Float3{});
      const Float3 b = normalizeOr(positions[tri[(k + 2) % 3]] - positions[tri[k]], Float3{});
      const float w = std::acos(std::clamp(dot(a, b), -1.0f, 1.0f));
      du[tri[k]] = du[tri[k]] + normalizeOr(gu, Float3{}) * w;
      dv[tri[k]] = dv[tri[k]] + normalizeOr(gv, Float3{}) * w;
    }
  }
  // Step 2: pool the gradients of seam copies whose charts are oriented alike.
  if (!geometricIndex.empty()) poolAlikeSeamCopies(geometricIndex, du, dv);
  // Step 3: Gram-Schmidt against the normal; handedness from the bitangent's side.
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Float3 n = normals[i];
    Float3 t = du[i] - n * dot(n, du[i]);
    if (length(t) < 1e-12f) {
      // No usable u direction (no UV area around the vertex): any unit vector orthogonal to n.
      const Float3 axis = std::abs(n.x) < 0.9f ? Float3{1, 0, 0} : Float3{0, 1, 0};
      t = axis - n * dot(n, axis);
    }
    t = normalizeOr(t, Float3{1, 0, 0});
    const float w = dot(cross(n, t), dv[i]) < 0.0f ? -1.0f : 1.0f;
    tangents[i] = {t.x, t.y, t.z, w};
  }
}

}  // namespace tissue::mesh
