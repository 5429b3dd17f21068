// The precomputed-topology, multi-threaded shading path (DeformableSurface::update) against
// the original scatter implementation of angle-weighted normals and tangent frames, kept here
// verbatim as the reference, on the committed organ meshes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::mesh {
namespace {

Float3 add(Float3 a, Float3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Float3 sub(Float3 a, Float3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Float3 scale(Float3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
float dot(Float3 a, Float3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Float3 cross(Float3 a, Float3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Float3 normalizeOr(Float3 a, Float3 fallback) {
  const float len = std::sqrt(dot(a, a));
  return len > 1e-20f ? scale(a, 1.0f / len) : fallback;
}
float cornerAngle(Float3 p, Float3 q, Float3 r) {
  return std::acos(
      std::clamp(dot(normalizeOr(sub(q, p), Float3{}), normalizeOr(sub(r, p), Float3{})), -1.0f, 1.0f));
}

/// The original per-triangle scatter of Thürmer and Wüthrich (1998) normals.
void referenceNormals(std::span<const Float3> p, std::span<const Triangle> tris, std::span<Float3> normals) {
  std::fill(normals.begin(), normals.end(), Float3{});
  for (const auto& t : tris) {
    const Float3 n = normalizeOr(cross(sub(p[t[1]], p[t[0]]), sub(p[t[2]], p[t[0]])), Float3{});
    for (int k = 0; k < 3; ++k)
      normals[t[k]] =
          add(normals[t[k]], scale(n, cornerAngle(p[t[k]], p[t[(k + 1) % 3]], p[t[(k + 2) % 3]])));
  }
  for (auto& n : normals)
    n = normalizeOr(n, Float3{0, 0, 1});
}

/// The original tangent frames: scatter, hash-map seam pooling, Gram-Schmidt.
void referenceTangents(std::span<const Float3> p, std::span<const Float2> uv, std::span<const Triangle> tris,
                       std::span<const Float3> normals, std::span<const std::uint32_t> geo,
                       std::span<Float4> tangents) {
  std::vector<Float3> du(p.size()), dv(p.size());
  for (const auto& t : tris) {
    const Float3 e1 = sub(p[t[1]], p[t[0]]), e2 = sub(p[t[2]], p[t[0]]);
    const float s1 = uv[t[1]].x - uv[t[0]].x, t1 = uv[t[1]].y - uv[t[0]].y;
    const float s2 = uv[t[2]].x - uv[t[0]].x, t2 = uv[t[2]].y - uv[t[0]].y;
    const float det = s1 * t2 - s2 * t1;
    if (std::abs(det) < 1e-20f) continue;
    const Float3 gu = normalizeOr(scale(sub(scale(e1, t2), scale(e2, t1)), 1.0f / det), Float3{});
    const Float3 gv = normalizeOr(scale(sub(scale(e2, s1), scale(e1, s2)), 1.0f / det), Float3{});
    for (int k = 0; k < 3; ++k) {
      const float w = cornerAngle(p[t[k]], p[t[(k + 1) % 3]], p[t[(k + 2) % 3]]);
      du[t[k]] = add(du[t[k]], scale(gu, w));
      dv[t[k]] = add(dv[t[k]], scale(gv, w));
    }
  }
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> copies;
  for (std::uint32_t i = 0; i < geo.size(); ++i)
    copies[geo[i]].push_back(i);
  const float cos45 = std::sqrt(0.5f);
  for (auto& [g, list] : copies) {
    std::vector<Float3> pu(list.size()), pv(list.size());
    for (std::size_t a = 0; a < list.size(); ++a)
      for (std::size_t b = 0; b < list.size(); ++b) {
        const bool alike = dot(normalizeOr(du[list[a]], {}), normalizeOr(du[list[b]], {})) > cos45 &&
                           dot(normalizeOr(dv[list[a]], {}), normalizeOr(dv[list[b]], {})) > cos45;
        if (a == b || alike) pu[a] = add(pu[a], du[list[b]]), pv[a] = add(pv[a], dv[list[b]]);
      }
    for (std::size_t a = 0; a < list.size(); ++a)
      du[list[a]] = pu[a], dv[list[a]] = pv[a];
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Float3 n = normals[i];
    Float3 t = sub(du[i], scale(n, dot(n, du[i])));
    if (std::sqrt(dot(t, t)) < 1e-12f) {
      const Float3 axis = std::abs(n.x) < 0.9f ? Float3{1, 0, 0} : Float3{0, 1, 0};
      t = sub(axis, scale(n, dot(n, axis)));
    }
    t = normalizeOr(t, Float3{1, 0, 0});
    tangents[i] = {t.x, t.y, t.z, dot(cross(n, t), dv[i]) < 0.0f ? -1.0f : 1.0f};
  }
}

/// The mesh pushed in by up to 5 mm along -z over its upper fifth (a smooth deformation).
std::vector<Float3> poked(std::span<const Float3> rest) {
  float lo = rest[0].z, hi = rest[0].z;
  for (const auto& p : rest)
    lo = std::min(lo, p.z), hi = std::max(hi, p.z);
  const float cut = hi - 0.2f * (hi - lo);
  std::vector<Float3> out(rest.begin(), rest.end());
  for (auto& p : out)
    if (p.z > cut) p.z -= 5.0f * (p.z - cut) / (hi - cut);
  return out;
}

class ShadingFastPath : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadingFastPath, MatchesTheReferenceAndIsThreadCountInvariant) {
  auto mesh = loadMesh(std::string(TISSUE_TEST_DATA_DIR) + "/meshes/" + GetParam(), {.requireUvs = true});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto one = DeformableSurface::create(*mesh, {}, 1);
  auto two = DeformableSurface::create(*mesh, {}, 2);
  ASSERT_TRUE(one.ok() && two.ok());
  EXPECT_EQ(one->threadCount(), 1u);
  EXPECT_EQ(two->threadCount(), 2u);
  const auto geo = poked(one->geometricRestPositions());
  one->update(geo);
  two->update(geo);

  // Reference: scatter normals per geometric vertex, copied to render vertices; tangents.
  const auto& m = one->mesh();
  std::vector<Float3> geoNormals(geo.size()), normals(m.positions.size());
  referenceNormals(geo, one->geometricTriangles(), geoNormals);
  for (std::size_t i = 0; i < normals.size(); ++i)
    normals[i] = geoNormals[m.geometricIndex[i]];
  std::vector<Float4> tangents(m.positions.size());
  referenceTangents(m.positions, m.uvs, m.triangles, normals, m.geometricIndex, tangents);

  // The public free functions on raw arrays follow the same path.
  std::vector<Float3> freeNormals(geo.size());
  computeVertexNormals(geo, one->geometricTriangles(), freeNormals);
  std::vector<Float4> freeTangents(m.positions.size());
  computeTangentFrames(m.positions, m.uvs, m.triangles, normals, freeTangents, m.geometricIndex);

  std::size_t flips = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Float3 n = one->normals()[i];
    const Float4 t = one->tangents()[i];
    EXPECT_NEAR(n.x, normals[i].x, 1e-6f) << i;
    EXPECT_NEAR(n.y, normals[i].y, 1e-6f) << i;
    EXPECT_NEAR(n.z, normals[i].z, 1e-6f) << i;
    EXPECT_NEAR(t.x, tangents[i].x, 1e-6f) << i;
    EXPECT_NEAR(t.y, tangents[i].y, 1e-6f) << i;
    EXPECT_NEAR(t.z, tangents[i].z, 1e-6f) << i;
    flips += t.w != tangents[i].w;
    // Bit-identical for 1 and 2 threads, and to the free functions.
    EXPECT_EQ(n, two->normals()[i]) << i;
    EXPECT_EQ(t, two->tangents()[i]) << i;
    EXPECT_EQ(n, freeNormals[m.geometricIndex[i]]) << i;
    EXPECT_EQ(t, freeTangents[i]) << i;
  }
  EXPECT_EQ(flips, 0u);
}

INSTANTIATE_TEST_SUITE_P(OrganMeshes, ShadingFastPath, ::testing::Values("liver.obj", "tube.obj"));

}  // namespace
}  // namespace tissue::mesh
