#include "tissue/mesh/triangle_geometry.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

/// One triangle, scalar: the reference arithmetic that the SSE path reproduces bit for bit.
void triangleGeometry(std::span<const Float3> positions, std::span<const Triangle> triangles,
                      std::span<const UvBasis> uvBases, std::size_t t, std::span<TriangleGeometry> out) {
  const auto& tri = triangles[t];
  const Float3 p[3] = {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
  TriangleGeometry& g = out[t];
  // Face normal from the two edges at corner 0.
  const Float3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  g.normal = normalizeOr(cross(e1, e2), Float3{});
  // Corner angles from the three unit edge directions: the two edges leaving corner k are
  // u[k] and -u[k+2], so three normalisations serve all three corners. Negation is exact,
  // so each angle equals acos(dot(unit(p[k+1]-p[k]), unit(p[k+2]-p[k]))) bit for bit.
  // The weights keep the library acos: a cheaper approximation would move them by more
  // than float rounding.
  const Float3 u[3] = {normalizeOr(e1, Float3{}), normalizeOr(p[2] - p[1], Float3{}),
                       normalizeOr(p[0] - p[2], Float3{})};
  for (int k = 0; k < 3; ++k) {
    const Float3 back = Float3{} - u[(k + 2) % 3];
    g.angles[std::size_t(k)] = std::acos(std::clamp(dot(u[k], back), -1.0f, 1.0f));
  }
  // UV gradients dP/du, dP/dv (Lengyel 2001), normalised.
  if (uvBases.empty() || !uvBases[t].hasUvArea) {
    g.dPdu = g.dPdv = Float3{};
    return;
  }
  const UvBasis& b = uvBases[t];
  g.dPdu = normalizeOr((e1 * b.t2 - e2 * b.t1) * b.r, Float3{});
  g.dPdv = normalizeOr((e2 * b.s1 - e1 * b.s2) * b.r, Float3{});
}

#if defined(__SSE2__)
// Four triangles at a time in SSE lanes. Every lane does the scalar path's IEEE operations in
// the same order (sqrt and division are correctly rounded in both), so the results are equal
// bit for bit; only acos stays scalar.
struct F4 {
  __m128 v;
};
inline F4 operator+(F4 a, F4 b) {
  return {_mm_add_ps(a.v, b.v)};
}
inline F4 operator-(F4 a, F4 b) {
  return {_mm_sub_ps(a.v, b.v)};
}
inline F4 operator*(F4 a, F4 b) {
  return {_mm_mul_ps(a.v, b.v)};
}
struct V4 {
  F4 x, y, z;
};
inline V4 operator-(const V4& a, const V4& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V4 operator*(const V4& a, F4 s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline F4 dot4(const V4& a, const V4& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V4 cross4(const V4& a, const V4& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// normalizeOr(a, 0) per lane.
inline V4 normalizeOrZero4(const V4& a) {
  const __m128 len = _mm_sqrt_ps(dot4(a, a).v);
  const __m128 keep = _mm_cmpgt_ps(len, _mm_set1_ps(1e-20f));
  const F4 inv{_mm_div_ps(_mm_set1_ps(1.0f), len)};
  const V4 n = a * inv;
  return {{_mm_and_ps(n.x.v, keep)}, {_mm_and_ps(n.y.v, keep)}, {_mm_and_ps(n.z.v, keep)}};
}
inline V4 load4(std::span<const Float3> p, const std::uint32_t (&i)[4]) {
  return {{_mm_setr_ps(p[i[0]].x, p[i[1]].x, p[i[2]].x, p[i[3]].x)},
          {_mm_setr_ps(p[i[0]].y, p[i[1]].y, p[i[2]].y, p[i[3]].y)},
          {_mm_setr_ps(p[i[0]].z, p[i[1]].z, p[i[2]].z, p[i[3]].z)}};
}
inline void store4(const V4& a, Float3 (&out)[4]) {
  float x[4], y[4], z[4];
  _mm_storeu_ps(x, a.x.v), _mm_storeu_ps(y, a.y.v), _mm_storeu_ps(z, a.z.v);
  for (int l = 0; l < 4; ++l)
    out[l] = {x[l], y[l], z[l]};
}

/// Triangles t .. t+3.
void fourTrianglesGeometry(std::span<const Float3> positions, std::span<const Triangle> triangles,
                           std::span<const UvBasis> uvBases, std::size_t t, std::span<TriangleGeometry> out) {
  std::uint32_t idx[3][4];
  for (int l = 0; l < 4; ++l)
    for (int k = 0; k < 3; ++k)
      idx[k][l] = triangles[t + std::size_t(l)][std::size_t(k)];
  const V4 p0 = load4(positions, idx[0]), p1 = load4(positions, idx[1]), p2 = load4(positions, idx[2]);
  const V4 e1 = p1 - p0, e2 = p2 - p0;
  Float3 normal[4];
  store4(normalizeOrZero4(cross4(e1, e2)), normal);
  const V4 unit[3] = {normalizeOrZero4(e1), normalizeOrZero4(p2 - p1), normalizeOrZero4(p0 - p2)};
  float cosine[3][4];
  for (int k = 0; k < 3; ++k) {
    const V4& b = unit[(k + 2) % 3];
    const V4 minusB = {F4{_mm_setzero_ps()} - b.x, F4{_mm_setzero_ps()} - b.y, F4{_mm_setzero_ps()} - b.z};
    _mm_storeu_ps(cosine[k], dot4(unit[k], minusB).v);
  }
  for (int l = 0; l < 4; ++l) {
    TriangleGeometry& g = out[t + std::size_t(l)];
    g.normal = normal[l];
    for (int k = 0; k < 3; ++k)
      g.angles[std::size_t(k)] = std::acos(std::clamp(cosine[k][l], -1.0f, 1.0f));
  }
  // UV gradients, lanes without UV area zeroed.
  if (uvBases.empty()) {
    for (int l = 0; l < 4; ++l)
      out[t + std::size_t(l)].dPdu = out[t + std::size_t(l)].dPdv = Float3{};
    return;
  }
  float s1[4], t1[4], s2[4], t2[4], r[4];
  for (int l = 0; l < 4; ++l) {
    const UvBasis& b = uvBases[t + std::size_t(l)];
    s1[l] = b.s1, t1[l] = b.t1, s2[l] = b.s2, t2[l] = b.t2, r[l] = b.r;
  }
  const auto f4 = [](const float(&a)[4]) { return F4{_mm_loadu_ps(a)}; };
  Float3 du[4], dv[4];
  store4(normalizeOrZero4((e1 * f4(t2) - e2 * f4(t1)) * f4(r)), du);
  store4(normalizeOrZero4((e2 * f4(s1) - e1 * f4(s2)) * f4(r)), dv);
  for (int l = 0; l < 4; ++l) {
    TriangleGeometry& g = out[t + std::size_t(l)];
    const bool hasUvArea = uvBases[t + std::size_t(l)].hasUvArea;
    g.dPdu = hasUvArea ? du[l] : Float3{};
    g.dPdv = hasUvArea ? dv[l] : Float3{};
  }
}
#endif

}  // namespace

void computeTriangleGeometry(std::span<const Float3> positions, std::span<const Triangle> triangles,
                             std::span<const UvBasis> uvBases, std::size_t first, std::size_t last,
                             std::span<TriangleGeometry> out) {
  std::size_t t = first;
#if defined(__SSE2__)
  for (; t + 4 <= last; t += 4)
    fourTrianglesGeometry(positions, triangles, uvBases, t, out);
#endif
  for (; t < last; ++t)
    triangleGeometry(positions, triangles, uvBases, t, out);
}

}  // namespace tissue::mesh
