#include "repair_mesh.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace tissue::mesh::detail {
namespace {

std::uint64_t undirectedKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

std::uint32_t copyPoint(std::vector<Float3>& points, std::vector<std::uint32_t>& source, std::uint32_t p) {
  points.push_back(points[p]);
  source.push_back(source[p]);
  return std::uint32_t(points.size() - 1);
}

/// Step 1: an edge keeps its first two faces; every later face on it gets copies of the edge's
/// two vertices.
void splitNonManifoldEdges(std::vector<Float3>& points, std::vector<std::uint32_t>& source,
                           std::vector<Triangle>& tris, TopologyRepairs& out) {
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(tris.size() * 2);
  std::unordered_map<std::uint64_t, char> overfull;
  for (auto& tri : tris) {
    bool detach[3] = {false, false, false};  // per corner: copy this vertex
    for (int k = 0; k < 3; ++k) {
      const auto key = undirectedKey(tri[k], tri[(k + 1) % 3]);
      auto it = uses.find(key);
      if (it != uses.end() && it->second >= 2) {
        detach[k] = detach[(k + 1) % 3] = true;
        overfull.emplace(key, 1);
      }
    }
    if (detach[0] || detach[1] || detach[2]) {
      ++out.detachedFaces;
      for (int k = 0; k < 3; ++k) {
        if (!detach[k]) continue;
        tri[k] = copyPoint(points, source, tri[k]);
        ++out.addedVertices;
      }
    }
    for (int k = 0; k < 3; ++k)
      ++uses[undirectedKey(tri[k], tri[(k + 1) % 3])];
  }
  out.nonManifoldEdges = overfull.size();
}

/// Union-find over the faces around one vertex.
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

/// Step 2: the faces around each vertex, joined where two share an edge at it; each fan beyond
/// the first gets its own copy of the vertex.
void splitBowTies(std::vector<Float3>& points, std::vector<std::uint32_t>& source,
                  std::vector<Triangle>& tris, TopologyRepairs& out) {
  const std::size_t pointCount = points.size();
  std::vector<std::vector<std::uint32_t>> around(pointCount);
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (auto v : tris[t])
      around[v].push_back(std::uint32_t(t));
  std::vector<std::uint32_t> parent;
  std::unordered_map<std::uint32_t, std::uint32_t> firstWithNeighbour;  // other vertex -> local face
  for (std::uint32_t v = 0; v < pointCount; ++v) {
    const auto& faces = around[v];
    if (faces.size() < 2) continue;
    parent.resize(faces.size());
    std::iota(parent.begin(), parent.end(), 0u);
    firstWithNeighbour.clear();
    for (std::uint32_t i = 0; i < faces.size(); ++i) {
      for (auto w : tris[faces[i]]) {
        if (w == v) continue;
        auto [it, inserted] = firstWithNeighbour.emplace(w, i);
        if (!inserted) parent[findRoot(parent, i)] = findRoot(parent, it->second);
      }
    }
    std::unordered_map<std::uint32_t, std::uint32_t> copyOfRoot;  // fan root -> vertex it uses
    const std::uint32_t firstRoot = findRoot(parent, 0);
    for (std::uint32_t i = 0; i < faces.size(); ++i) {
      const std::uint32_t root = findRoot(parent, i);
      if (root == firstRoot) continue;
      auto [it, inserted] = copyOfRoot.emplace(root, 0u);
      if (inserted) {
        it->second = copyPoint(points, source, v);
        ++out.addedVertices;
      }
      for (auto& corner : tris[faces[i]])
        if (corner == v) corner = it->second;
    }
    if (!copyOfRoot.empty()) ++out.bowTieVertices;
  }
}

/// Step 3: breadth-first over edge neighbours; a neighbour that runs a shared edge the same way
/// is flipped. Per component the smaller set is flipped, so a mostly right mesh keeps its sense.
void orientConsistently(std::vector<Triangle>& tris, TopologyRepairs& out) {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> byEdge;
  byEdge.reserve(tris.size() * 2);
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k)
      byEdge[undirectedKey(tris[t][k], tris[t][(k + 1) % 3])].push_back(std::uint32_t(t));
  const auto runs = [&](const Triangle& tri, bool flipped, std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t from = tri[k], to = tri[(k + 1) % 3];
      if (flipped ? (from == b && to == a) : (from == a && to == b)) return true;
    }
    return false;
  };
  std::vector<signed char> flip(tris.size(), -1);  // -1 unvisited, 0 kept, 1 flipped
  std::vector<std::uint32_t> component;
  for (std::size_t seed = 0; seed < tris.size(); ++seed) {
    if (flip[seed] >= 0) continue;
    component.assign(1, std::uint32_t(seed));
    flip[seed] = 0;
    for (std::size_t head = 0; head < component.size(); ++head) {
      const std::uint32_t t = component[head];
      const bool tf = flip[t] == 1;
      for (int k = 0; k < 3; ++k) {
        std::uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
        if (tf) std::swap(a, b);  // the edge as t now runs it
        for (auto n : byEdge[undirectedKey(a, b)]) {
          if (n == t || flip[n] >= 0) continue;
          flip[n] = runs(tris[n], false, a, b) ? 1 : 0;  // a neighbour must run it b -> a
          component.push_back(n);
        }
      }
    }
    const auto flipped = std::size_t(
        std::count_if(component.begin(), component.end(), [&](std::uint32_t t) { return flip[t] == 1; }));
    const bool invert = 2 * flipped > component.size();
    for (auto t : component) {
      if ((flip[t] == 1) != invert) {
        std::swap(tris[t][1], tris[t][2]);
        ++out.flippedFaces;
      }
    }
  }
}

}  // namespace

TopologyRepairs repairTopology(std::vector<Float3>& points, std::vector<std::uint32_t>& pointSource,
                               std::vector<Triangle>& triangles) {
  TopologyRepairs out;
  splitNonManifoldEdges(points, pointSource, triangles, out);
  splitBowTies(points, pointSource, triangles, out);
  orientConsistently(triangles, out);
  return out;
}

}  // namespace tissue::mesh::detail
