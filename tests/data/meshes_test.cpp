// Invariants of the committed meshes in data/meshes (counts, sizes, topology, orientation, UVs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "obj_reader.h"
#include "uv_overlap.h"

namespace tissue::datatest {
namespace {

ObjMesh load(const char* name) {
  auto mesh = readObj(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "meshes" / (std::string(name) + ".obj"));
  EXPECT_TRUE(mesh.ok()) << (mesh.ok() ? "" : mesh.error().message);
  return mesh.ok() ? *mesh : ObjMesh{};
}

struct Box {
  Float3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  Float3 size() const { return {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}; }
};

Box boundingBox(const ObjMesh& m) {
  Box b;
  for (const Float3& p : m.positions) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

using Edge = std::pair<std::uint32_t, std::uint32_t>;

/// Count of every directed edge (a -> b) over all triangles.
std::map<Edge, int> directedEdges(const ObjMesh& m) {
  std::map<Edge, int> edges;
  for (const Triangle& t : m.triangles) {
    for (int k = 0; k < 3; ++k)
      ++edges[{t[k], t[(k + 1) % 3]}];
  }
  return edges;
}

/// Lengths of the boundary loops (directed edges without their opposite), sorted.
std::vector<std::size_t> boundaryLoops(const ObjMesh& m) {
  const auto edges = directedEdges(m);
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& [e, count] : edges) {
    if (!edges.count({e.second, e.first})) next[e.first] = e.second;
  }
  std::vector<std::size_t> loops;
  std::set<std::uint32_t> seen;
  for (const auto& [start, unused] : next) {
    if (seen.count(start)) continue;
    std::size_t length = 0;
    for (std::uint32_t v = start; !seen.count(v) && next.count(v); v = next.at(v)) {
      seen.insert(v);
      ++length;
    }
    loops.push_back(length);
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

double triangleArea(const ObjMesh& m, const Triangle& t, Float3* normal = nullptr) {
  const Float3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  if (normal) *normal = {float(nx), float(ny), float(nz)};
  return 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
}

/// Signed volume (mm^3) enclosed by the triangles (divergence theorem: sum of a . (b x c) / 6).
double signedVolume(const ObjMesh& m) {
  double v = 0.0;
  for (const Triangle& t : m.triangles) {
    const Float3 fa = m.positions[t[0]], fb = m.positions[t[1]], fc = m.positions[t[2]];
    const double a[3] = {fa.x, fa.y, fa.z}, b[3] = {fb.x, fb.y, fb.z}, c[3] = {fc.x, fc.y, fc.z};
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6.0;
  }
  return v;
}

void expectUvsInUnitSquare(const ObjMesh& m) {
  for (const Float2& t : m.uvs) {
    ASSERT_GE(t.x, 0.0f);
    ASSERT_LE(t.x, 1.0f);
    ASSERT_GE(t.y, 0.0f);
    ASSERT_LE(t.y, 1.0f);
  }
}

void expectNoDegenerateTriangles(const ObjMesh& m, double minAreaMm2) {
  for (const Triangle& t : m.triangles) {
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    ASSERT_GT(triangleArea(m, t), minAreaMm2);
  }
}

/// Gutter between charts: 2 texels at 1024 x 1024 (the generator leaves 8).
constexpr double kGutter = 2.0 / 1024.0;

TEST(DataMeshes, PatchCountsSizeAndBorder) {
  const ObjMesh m = load("patch");
  EXPECT_GE(m.positions.size(), 9000u);
  EXPECT_LE(m.positions.size(), 11000u);
  const Float3 size = boundingBox(m).size();
  EXPECT_NEAR(size.x, 80.0f, 1.0f);
  EXPECT_NEAR(size.y, 60.0f, 1.0f);
  EXPECT_GT(size.z, 2.0f);  // curved and bumpy, not flat
  EXPECT_LT(size.z, 20.0f);
  expectUvsInUnitSquare(m);
  expectNoDegenerateTriangles(m, 1e-3);
  // One open border loop around the 115 x 87 grid: 2 * (114 + 86) edges.
  EXPECT_EQ(boundaryLoops(m), std::vector<std::size_t>{400});
  // Outside is +z: every triangle faces up.
  for (const Triangle& t : m.triangles) {
    Float3 n;
    triangleArea(m, t, &n);
    ASSERT_GT(n.z, 0.0f);
  }
}

TEST(DataMeshes, LiverIsClosedOutwardGenusZeroManifold) {
  const ObjMesh m = load("liver");
  EXPECT_GE(m.positions.size(), 10000u);
  EXPECT_LE(m.positions.size(), 20000u);
  const Float3 size = boundingBox(m).size();
  EXPECT_NEAR(size.x, 180.0f, 20.0f);
  EXPECT_NEAR(size.y, 120.0f, 15.0f);
  EXPECT_NEAR(size.z, 80.0f, 12.0f);
  expectUvsInUnitSquare(m);
  expectNoDegenerateTriangles(m, 1e-2);
  // Every directed edge exactly once, and its opposite exactly once: a closed, consistently
  // oriented 2-manifold (no boundary, no non-manifold edge).
  const auto edges = directedEdges(m);
  for (const auto& [e, count] : edges) {
    ASSERT_EQ(count, 1) << e.first << " -> " << e.second;
    ASSERT_EQ(edges.count({e.second, e.first}), 1u) << e.first << " -> " << e.second;
  }
  std::set<std::uint32_t> used;
  for (const Triangle& t : m.triangles)
    used.insert(t.begin(), t.end());
  EXPECT_EQ(used.size(), m.positions.size()) << "unreferenced vertices";
  // Euler characteristic V - E + F = 2: genus 0.
  const long chi = long(m.positions.size()) - long(edges.size() / 2) + long(m.triangles.size());
  EXPECT_EQ(chi, 2);
  // Outward orientation: positive enclosed volume, a good fraction of the bounding box.
  const double volume = signedVolume(m);
  const double boxVolume = double(size.x) * double(size.y) * double(size.z);
  EXPECT_GT(volume, 0.25 * boxVolume);
  EXPECT_LT(volume, 0.6 * boxVolume);
  // Six UV charts (the cube faces).
  const std::vector<int> charts = uvCharts(m.uvTriangles, m.uvs.size());
  EXPECT_EQ(std::set<int>(charts.begin(), charts.end()).size(), 6u);
}

TEST(DataMeshes, TubeCountsAndOpenEnds) {
  const ObjMesh m = load("tube");
  EXPECT_EQ(m.positions.size(), 64u * 150u);
  EXPECT_EQ(m.uvs.size(), 65u * 150u);  // the u seam duplicates one vt per ring
  expectUvsInUnitSquare(m);
  expectNoDegenerateTriangles(m, 1e-3);
  // Two open ends of 64 edges each; everything else manifold.
  EXPECT_EQ(boundaryLoops(m), (std::vector<std::size_t>{64, 64}));
  for (const auto& [e, count] : directedEdges(m))
    ASSERT_EQ(count, 1);
  // Outward: capping the ends with fans about their centres encloses a positive volume.
  ObjMesh capped = m;
  for (int end = 0; end < 2; ++end) {
    Float3 c;
    for (int i = 0; i < 64; ++i) {
      const Float3 p = m.positions[std::size_t(end * 149 * 64 + i)];
      c = {c.x + p.x / 64, c.y + p.y / 64, c.z + p.z / 64};
    }
    const auto centre = std::uint32_t(capped.positions.size());
    capped.positions.push_back(c);
    for (std::uint32_t i = 0; i < 64; ++i) {
      const std::uint32_t a = std::uint32_t(end * 149 * 64) + i,
                          b = std::uint32_t(end * 149 * 64) + (i + 1) % 64;
      capped.triangles.push_back(end == 0 ? Triangle{centre, b, a} : Triangle{centre, a, b});
    }
  }
  EXPECT_GT(signedVolume(capped), 0.0);
  const Float3 size = boundingBox(m).size();
  EXPECT_GT(std::max({size.x, size.y, size.z}), 130.0f);
}

TEST(DataMeshes, UvAtlasesHaveNoOverlapsAndKeepGutters) {
  for (const char* name : {"patch", "liver", "tube"}) {
    const ObjMesh m = load(name);
    const auto conflicts = findUvConflicts(m.uvs, m.uvTriangles, kGutter);
    EXPECT_TRUE(conflicts.empty()) << name << ": triangles " << conflicts.front().first << " and "
                                   << conflicts.front().second << " gap " << conflicts.front().separation;
  }
}

TEST(DataMeshes, OverlapCheckCatchesOverlappingAndTooCloseCharts) {
  // The check itself must fail on bad atlases: two charts of two triangles each.
  const std::vector<Triangle> tris = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  const auto square = [](float x, float y, float s) {
    return std::vector<Float2>{{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}};
  };
  std::vector<Float2> uvs = square(0.1f, 0.1f, 0.3f);
  const auto apart = square(0.5f, 0.1f, 0.3f), overlapping = square(0.3f, 0.3f, 0.3f),
             tooClose = square(0.4005f, 0.1f, 0.3f);
  for (const auto& [second, expectConflict] :
       {std::pair{apart, false}, std::pair{overlapping, true}, std::pair{tooClose, true}}) {
    std::vector<Float2> all = uvs;
    all.insert(all.end(), second.begin(), second.end());
    EXPECT_EQ(!findUvConflicts(all, tris, kGutter).empty(), expectConflict);
  }
  // Within one chart, a folded triangle overlapping its neighbour is caught too.
  const std::vector<Float2> folded = {{0.1f, 0.1f}, {0.4f, 0.1f}, {0.4f, 0.4f}, {0.35f, 0.05f}};
  EXPECT_FALSE(findUvConflicts(folded, {{0, 1, 2}, {0, 2, 3}}, kGutter).empty());
}

}  // namespace
}  // namespace tissue::datatest
