#include "validate_mesh.h"

#include <Eigen/Geometry>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <unordered_map>

#include "tissue/mesh/load_mesh.h"
#include "vec3.h"

namespace tissue::mesh::detail {
namespace {

std::string formatPoint(Float3 p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(a) << 32) | b;
}

/// Directed-edge bookkeeping: an undirected edge in more than two triangles, or a directed edge
/// in two triangles (neighbours oriented against each other), is not a consistent 2-manifold.
Result<void> checkEdges(std::span<const Triangle> triangles, const std::string& source,
                        const TriangleLabel& label) {
  std::unordered_map<std::uint64_t, std::uint32_t> directed;  // directed edge -> triangle
  std::unordered_map<std::uint64_t, std::uint32_t> uses;      // undirected edge -> count
  directed.reserve(triangles.size() * 3);
  uses.reserve(triangles.size() * 2);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      if (++uses[edgeKey(std::min(a, b), std::max(a, b))] > 2) {
        return Error{source + ": " + label(t) + " is non-manifold: its edge between vertices " +
                     std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                     " is shared by more than two faces; remove the extra face or split the edge"};
      }
      auto [it, inserted] = directed.emplace(edgeKey(a, b), std::uint32_t(t));
      if (!inserted) {
        return Error{source + ": " + label(t) + " is oriented against " + label(it->second) +
                     " (both run the edge from vertex " + std::to_string(a + 1) + " to " +
                     std::to_string(b + 1) + "); flip one of them so neighbouring faces agree"};
      }
    }
  }
  return {};
}

/// A vertex whose triangles form two or more separate fans (two sheets touching at a point):
/// OpenMesh's half-edge structure refuses such a face, which is how it is detected here.
Result<void> checkVertexFans(std::span<const Float3> points, std::span<const Triangle> triangles,
                             const std::string& source, const TriangleLabel& label) {
  OpenMesh::TriMesh_ArrayKernelT<> mesh;
  std::vector<OpenMesh::VertexHandle> handles(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    handles[i] = mesh.add_vertex(OpenMesh::Vec3f(points[i].x, points[i].y, points[i].z));
  std::ostringstream silenced;  // OpenMesh prints "complex vertex" itself; the Error below says it
  auto* old = std::cerr.rdbuf(silenced.rdbuf());
  std::size_t bad = triangles.size();
  for (std::size_t t = 0; t < triangles.size() && bad == triangles.size(); ++t) {
    const auto& tri = triangles[t];
    if (!mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid()) bad = t;
  }
  std::cerr.rdbuf(old);
  if (bad == triangles.size()) return {};
  return Error{source + ": " + label(bad) +
               " is non-manifold: one of its vertices joins two separate surface sheets; split that vertex "
               "or remove the face"};
}

}  // namespace

bool isZeroAreaTriangle(std::span<const Float3> points, const Triangle& t) {
  // In double: float inputs make collinear decimal points only approximately collinear, so the
  // test is relative: height below 2e-6 of the longest edge (far below any renderable sliver).
  const Eigen::Vector3d a(points[t[0]].x, points[t[0]].y, points[t[0]].z);
  const Eigen::Vector3d b(points[t[1]].x, points[t[1]].y, points[t[1]].z);
  const Eigen::Vector3d c(points[t[2]].x, points[t[2]].y, points[t[2]].z);
  const double longest2 = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
  return 0.5 * (b - a).cross(c - a).norm() <= 1e-6 * longest2;
}

Result<void> validateGeometry(std::span<const Float3> points, std::span<const Triangle> triangles,
                              const std::string& source, const TriangleLabel& label) {
  if (points.empty() || triangles.empty()) {
    return Error{source + ": the mesh has no " + std::string(points.empty() ? "vertices" : "faces") +
                 "; give a file with at least one triangle"};
  }
  // Step 1: finite coordinates.
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!isFinite(points[i])) {
      return Error{source + ": vertex " + std::to_string(i + 1) + " has a non-finite coordinate " +
                   formatPoint(points[i]) + "; replace NaN/Inf coordinates with real numbers"};
    }
  }
  // Step 2: indices in range and non-degenerate triangles (a repeated vertex, or no area).
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (auto v : tri) {
      if (v >= points.size()) {
        return Error{source + ": " + label(t) + " refers to vertex " + std::to_string(std::int64_t(v) + 1) +
                     " but the file has " + std::to_string(points.size()) +
                     " vertices; fix the face's indices"};
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      return Error{source + ": " + label(t) + " is degenerate: it uses vertex " +
                   std::to_string((tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1]) + 1) +
                   " twice; remove the face"};
    }
    if (isZeroAreaTriangle(points, tri)) {
      return Error{source + ": " + label(t) +
                   " is degenerate: its three vertices are collinear (zero area); "
                   "remove the face or move a vertex"};
    }
  }
  // Step 3: manifold topology.
  if (auto r = checkEdges(triangles, source, label); !r) return r;
  return checkVertexFans(points, triangles, source, label);
}

}  // namespace tissue::mesh::detail

namespace tissue::mesh {

Result<void> validateMesh(const SurfaceMesh& mesh, const std::string& source) {
  if (mesh.geometricIndex.size() != mesh.positions.size()) {
    return Error{source + ": geometricIndex has " + std::to_string(mesh.geometricIndex.size()) +
                 " entries for " + std::to_string(mesh.positions.size()) +
                 " vertices; build it with one entry per vertex"};
  }
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
    return Error{source + ": " + std::to_string(mesh.uvs.size()) + " texture coordinates for " +
                 std::to_string(mesh.positions.size()) + " vertices; give one per vertex or none"};
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (auto v : mesh.triangles[t]) {
      if (v >= mesh.positions.size()) {
        return Error{source + ": triangle " + std::to_string(t + 1) + " refers to vertex " +
                     std::to_string(v + 1) + " of " + std::to_string(mesh.positions.size()) +
                     "; fix the index"};
      }
    }
  }
  for (auto g : mesh.geometricIndex) {
    if (g >= mesh.geometricVertexCount) {
      return Error{source + ": geometricIndex refers to geometric vertex " + std::to_string(g + 1) + " of " +
                   std::to_string(mesh.geometricVertexCount) + "; fix geometricVertexCount or the index"};
    }
  }
  std::vector<Float3> geo(mesh.geometricVertexCount);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    geo[mesh.geometricIndex[i]] = mesh.positions[i];
  std::vector<Triangle> geoTris(mesh.triangles.size());
  for (std::size_t t = 0; t < geoTris.size(); ++t)
    for (int k = 0; k < 3; ++k)
      geoTris[t][k] = mesh.geometricIndex[mesh.triangles[t][k]];
  return detail::validateGeometry(geo, geoTris, source,
                                  [](std::size_t t) { return "triangle " + std::to_string(t + 1); });
}

}  // namespace tissue::mesh
