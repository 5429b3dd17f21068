#include "tissue/mesh/load_mesh.h"

#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>

#include "openmesh_importer.h"
#include "repair_mesh.h"
#include "validate_mesh.h"

namespace tissue::mesh {
namespace {

/// Splits geometric vertices into render vertices, one per distinct (vertex, uv) pair.
class SeamSplitter {
 public:
  SeamSplitter(SurfaceMesh& out, bool withUvs) : m_out(out), m_withUvs(withUvs) {}

  /// `point` is the geometric point (a repair's copy has its own), `source` the file's vertex.
  std::uint32_t vertex(std::uint32_t point, std::uint32_t source, Float3 position, Float2 uv) {
    std::uint64_t key = std::uint64_t(std::uint32_t(point)) << 32;
    if (m_withUvs) {
      // Corners whose UVs are bitwise equal share a render vertex; different UVs mean a seam.
      std::uint32_t u, v;
      std::memcpy(&u, &uv.x, 4);
      std::memcpy(&v, &uv.y, 4);
      auto& perPoint = m_uvVariants[std::uint32_t(point)];
      const std::uint64_t uvKey = (std::uint64_t(u) << 32) | v;
      auto [it, inserted] = perPoint.emplace(uvKey, std::uint32_t(m_out.positions.size()));
      if (!inserted) return it->second;
      push(point, source, position, uv);
      return it->second;
    }
    auto [it, inserted] = m_plain.emplace(key, std::uint32_t(m_out.positions.size()));
    if (inserted) push(point, source, position, uv);
    return it->second;
  }

 private:
  void push(std::uint32_t point, std::uint32_t source, Float3 position, Float2 uv) {
    m_out.positions.push_back(position);
    if (m_withUvs) m_out.uvs.push_back(uv);
    // Geometric vertices are numbered in order of first use, so points no face uses are dropped.
    auto [it, inserted] = m_compact.emplace(std::uint32_t(point), m_out.geometricVertexCount);
    if (inserted) {
      ++m_out.geometricVertexCount;
      m_out.geometricSourceIndex.push_back(source);
    }
    m_out.geometricIndex.push_back(it->second);
  }
  SurfaceMesh& m_out;
  bool m_withUvs;
  std::unordered_map<std::uint32_t, std::map<std::uint64_t, std::uint32_t>> m_uvVariants;
  std::unordered_map<std::uint64_t, std::uint32_t> m_plain;
  std::unordered_map<std::uint32_t, std::uint32_t> m_compact;
};

/// Where the UVs come from: per corner (OBJ vt), per vertex (PLY/OFF), or none.
enum class UvSource { None, Corner, Vertex };

Result<UvSource> uvSourceOf(const detail::RawMesh& raw, const std::string& source) {
  bool anyCorner = false, allCorner = true;
  for (std::size_t f = 0; f < raw.polygons.size(); ++f) {
    if (raw.polygons[f].size() < 3) continue;  // a line element, handled by the caller
    const bool has = raw.cornerUvs[f].size() == raw.polygons[f].size();
    anyCorner |= has;
    allCorner &= has;
    if (anyCorner && !allCorner) {
      return Error{source + ": face " + std::to_string(f + 1) +
                   " has no texture coordinates while earlier faces do; give every face UVs or none"};
    }
  }
  if (anyCorner && allCorner) return UvSource::Corner;
  if (!raw.vertexUvs.empty() && raw.vertexUvs.size() == raw.points.size()) return UvSource::Vertex;
  return UvSource::None;
}

/// One warning line per kind of repair made, with its counts.
void reportRepairs(const detail::TopologyRepairs& r, const std::string& source, LoadReport& rep) {
  rep.splitNonManifoldEdges = r.nonManifoldEdges;
  rep.splitBowTieVertices = r.bowTieVertices;
  rep.flippedFaces = r.flippedFaces;
  if (r.nonManifoldEdges > 0)
    rep.warnings.push_back(source + ": split " + std::to_string(r.nonManifoldEdges) +
                           " non-manifold edges (shared by more than two faces): detached " +
                           std::to_string(r.detachedFaces) + " faces from them");
  if (r.bowTieVertices > 0)
    rep.warnings.push_back(source + ": split " + std::to_string(r.bowTieVertices) +
                           " bow-tie vertices (joining separate surface sheets); " +
                           std::to_string(r.addedVertices) + " vertices added by the splits");
  if (r.flippedFaces > 0)
    rep.warnings.push_back(source + ": flipped " + std::to_string(r.flippedFaces) +
                           " faces to orient them consistently with their neighbours");
}

/// Points no triangle uses: how many, and the first (0-based).
struct Unused {
  std::size_t count = 0;
  std::size_t first = 0;
};
Unused countUnused(std::size_t pointCount, const std::vector<Triangle>& tris) {
  std::vector<char> used(pointCount, 0);
  for (const auto& tri : tris)
    for (auto v : tri)
      used[v] = 1;
  Unused out;
  for (std::size_t i = pointCount; i-- > 0;)
    if (!used[i]) {
      ++out.count;
      out.first = i;
    }
  return out;
}

}  // namespace

Result<SurfaceMesh> loadMesh(const std::filesystem::path& path, const LoadOptions& options,
                             LoadReport* report) {
  LoadReport localReport;
  LoadReport& rep = report ? *report : localReport;
  const std::string source = path.string();
  auto raw = detail::readRawMesh(path);
  if (!raw) return raw.error();
  if (!(options.scaleToMm > 0.0f) || !std::isfinite(options.scaleToMm)) {
    return Error{source + ": scale " + std::to_string(options.scaleToMm) +
                 " mm per unit is invalid; give a positive scale"};
  }
  rep.warnings.insert(rep.warnings.end(), raw->notes.begin(), raw->notes.end());
  auto uvSource = uvSourceOf(*raw, source);
  if (!uvSource) return uvSource.error();
  if (options.requireUvs && *uvSource == UvSource::None) {
    return Error{source +
                 ": the mesh has no texture coordinates but they are needed (tangent frames, texture-space "
                 "lighting); export it with UVs or use a method that does not need them"};
  }
  // Step 1: geometric points and triangles (fan triangulation), with face labels for errors.
  std::vector<Float3> points(raw->points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = raw->points[i];
    points[i] = {p[0] * options.scaleToMm, p[1] * options.scaleToMm, p[2] * options.scaleToMm};
  }
  const auto faceName = [&](std::size_t f) {
    return "face " + std::to_string(f + 1) +
           (f < raw->polygonLines.size() ? " (line " + std::to_string(raw->polygonLines[f]) + ")" : "");
  };
  std::vector<Triangle> geoTris;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> origin;  // (face, corner of its fan)
  for (std::size_t f = 0; f < raw->polygons.size(); ++f) {
    const auto& poly = raw->polygons[f];
    if (poly.size() < 3) {
      if (options.strict) {
        return Error{source + ": " + faceName(f) + " has " + std::to_string(poly.size()) +
                     " vertices; a face needs at least three (write lines as 'l', or drop the face)"};
      }
      if (rep.droppedLineElements++ == 0)
        rep.warnings.push_back(source + ": " + faceName(f) +
                               " has fewer than three vertices; ignored as a line element");
      continue;
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      for (int idx : {poly[0], poly[k], poly[k + 1]}) {
        if (idx < 0 || std::size_t(idx) >= points.size()) {
          return Error{source + ": " + faceName(f) + " refers to vertex " + std::to_string(idx + 1) +
                       " but the file has " + std::to_string(points.size()) +
                       " vertices; fix the face's indices"};
        }
      }
      const Triangle tri{std::uint32_t(poly[0]), std::uint32_t(poly[k]), std::uint32_t(poly[k + 1])};
      const bool distinct = tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2];
      if (!options.strict && distinct && detail::isZeroAreaTriangle(points, tri)) {
        if (rep.droppedZeroAreaFaces++ == 0)
          rep.warnings.push_back(source + ": " + faceName(f) +
                                 " has zero area; dropped (and any further ones)");
        continue;
      }
      geoTris.push_back(tri);
      origin.emplace_back(std::uint32_t(f), std::uint32_t(k));
    }
  }
  const auto label = [&](std::size_t t) {
    const auto [f, k] = origin[t];
    const bool fan = raw->polygons[f].size() > 3;
    return faceName(f) + (fan ? " (triangle " + std::to_string(k) + " of its fan)" : "");
  };
  // Step 2: lenient repairs (strict leaves the defects to validation, which refuses them).
  std::vector<std::uint32_t> pointSource(points.size());
  for (std::size_t i = 0; i < pointSource.size(); ++i)
    pointSource[i] = std::uint32_t(i);
  if (!options.strict) reportRepairs(detail::repairTopology(points, pointSource, geoTris), source, rep);
  if (auto ok = detail::validateGeometry(points, geoTris, source, label); !ok) return ok.error();
  if (auto unused = countUnused(points.size(), geoTris); unused.count > 0) {
    if (options.strict) {
      return Error{source + ": vertex " + std::to_string(unused.first + 1) + " (and " +
                   std::to_string(unused.count - 1) +
                   " more) is used by no face; remove unused vertices or load without --strict to drop them"};
    }
    rep.droppedUnusedVertices = unused.count;
    rep.warnings.push_back(source + ": dropped " + std::to_string(unused.count) +
                           " vertices that no face uses (the first is vertex " +
                           std::to_string(unused.first + 1) + ")");
  }

  // Step 3: render vertices, split where the UVs of a point differ between faces (seams).
  SurfaceMesh mesh;
  SeamSplitter splitter(mesh, *uvSource != UvSource::None);
  mesh.triangles.resize(geoTris.size());
  for (std::size_t t = 0; t < geoTris.size(); ++t) {
    const auto [f, k] = origin[t];
    const std::size_t corners[3] = {0, k, k + 1};
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t point = geoTris[t][c];
      const std::size_t fileVertex = pointSource[point];
      Float2 uv{};
      if (*uvSource == UvSource::Corner) {
        const auto& cuv = raw->cornerUvs[f][corners[c]];
        uv = {cuv[0], cuv[1]};
      } else if (*uvSource == UvSource::Vertex) {
        uv = {raw->vertexUvs[fileVertex][0], raw->vertexUvs[fileVertex][1]};
      }
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        return Error{source + ": " + label(t) + " has a non-finite texture coordinate; fix the file's UVs"};
      }
      mesh.triangles[t][c] = splitter.vertex(point, std::uint32_t(fileVertex), points[point], uv);
    }
  }
  if (rep.droppedZeroAreaFaces > 1)
    rep.warnings.push_back(source + ": dropped " + std::to_string(rep.droppedZeroAreaFaces) +
                           " zero-area faces in all");
  return mesh;
}

}  // namespace tissue::mesh
