// OpenMesh adapter, reading half (see openmesh_importer.h for why a raw importer).
#include "openmesh_importer.h"

#include "tissue/volume/vtk_surface.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string_view>

namespace tissue::mesh::detail {
namespace {

namespace OM = OpenMesh;
using OM::IO::BaseImporter;

/// Records every element OpenMesh's readers report; ignores colours, normals and status.
class RawImporter final : public BaseImporter {
 public:
  explicit RawImporter(RawMesh& out) : m_out(out) {}

  OM::VertexHandle add_vertex(const OM::Vec3f& p) override {
    m_out.points.push_back({p[0], p[1], p[2]});
    return OM::VertexHandle(int(m_out.points.size()) - 1);
  }
  OM::VertexHandle add_vertex() override { return add_vertex(OM::Vec3f(0, 0, 0)); }
  OM::HalfedgeHandle add_edge(OM::VertexHandle, OM::VertexHandle) override { return OM::HalfedgeHandle(); }
  OM::FaceHandle add_face(const VHandles& handles) override {
    std::vector<int> polygon(handles.size());
    std::transform(handles.begin(), handles.end(), polygon.begin(), [](auto h) { return h.idx(); });
    m_out.polygons.push_back(std::move(polygon));
    m_out.cornerUvs.emplace_back();
    return OM::FaceHandle(int(m_out.polygons.size()) - 1);
  }
  OM::FaceHandle add_face(OM::HalfedgeHandle) override { return OM::FaceHandle(); }
  void add_face_texcoords(OM::FaceHandle fh, OM::VertexHandle, const std::vector<OM::Vec2f>& uvs) override {
    if (!fh.is_valid() || std::size_t(fh.idx()) >= m_out.cornerUvs.size()) return;
    auto& corners = m_out.cornerUvs[std::size_t(fh.idx())];
    corners.clear();
    for (const auto& uv : uvs)
      corners.push_back({uv[0], uv[1]});
  }
  void add_face_texcoords(OM::FaceHandle fh, OM::VertexHandle vh,
                          const std::vector<OM::Vec3f>& uvs) override {
    std::vector<OM::Vec2f> uv2;
    for (const auto& uv : uvs)
      uv2.emplace_back(uv[0], uv[1]);
    add_face_texcoords(fh, vh, uv2);
  }
  void set_texcoord(OM::VertexHandle vh, const OM::Vec2f& uv) override {
    if (!vh.is_valid()) return;
    if (m_out.vertexUvs.size() <= std::size_t(vh.idx())) m_out.vertexUvs.resize(std::size_t(vh.idx()) + 1);
    m_out.vertexUvs[std::size_t(vh.idx())] = {uv[0], uv[1]};
  }
  void set_texcoord(OM::VertexHandle vh, const OM::Vec3f& uv) override {
    set_texcoord(vh, OM::Vec2f(uv[0], uv[1]));
  }
  void set_point(OM::VertexHandle vh, const OM::Vec3f& p) override {
    if (vh.is_valid() && std::size_t(vh.idx()) < m_out.points.size())
      m_out.points[std::size_t(vh.idx())] = {p[0], p[1], p[2]};
  }

  // Attributes the mesh module does not use.
  void set_face_texindex(OM::FaceHandle, int) override {}
  void set_halfedge(OM::VertexHandle, OM::HalfedgeHandle) override {}
  void set_normal(OM::VertexHandle, const OM::Vec3f&) override {}
  void set_normal(OM::VertexHandle, const OM::Vec3d&) override {}
  void set_color(OM::VertexHandle, const OM::Vec3uc&) override {}
  void set_color(OM::VertexHandle, const OM::Vec4uc&) override {}
  void set_color(OM::VertexHandle, const OM::Vec3f&) override {}
  void set_color(OM::VertexHandle, const OM::Vec4f&) override {}
  void set_status(OM::VertexHandle, const OM::Attributes::StatusInfo&) override {}
  void set_next(OM::HalfedgeHandle, OM::HalfedgeHandle) override {}
  void set_face(OM::HalfedgeHandle, OM::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OM::HalfedgeHandle, const OM::Vec2f&) override {}
  void set_texcoord(OM::HalfedgeHandle, const OM::Vec3f&) override {}
  void set_status(OM::HalfedgeHandle, const OM::Attributes::StatusInfo&) override {}
  void set_color(OM::EdgeHandle, const OM::Vec3uc&) override {}
  void set_color(OM::EdgeHandle, const OM::Vec4uc&) override {}
  void set_color(OM::EdgeHandle, const OM::Vec3f&) override {}
  void set_color(OM::EdgeHandle, const OM::Vec4f&) override {}
  void set_status(OM::EdgeHandle, const OM::Attributes::StatusInfo&) override {}
  void set_normal(OM::FaceHandle, const OM::Vec3f&) override {}
  void set_normal(OM::FaceHandle, const OM::Vec3d&) override {}
  void set_color(OM::FaceHandle, const OM::Vec3uc&) override {}
  void set_color(OM::FaceHandle, const OM::Vec4uc&) override {}
  void set_color(OM::FaceHandle, const OM::Vec3f&) override {}
  void set_color(OM::FaceHandle, const OM::Vec4f&) override {}
  void set_status(OM::FaceHandle, const OM::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

  size_t n_vertices() const override { return m_out.points.size(); }
  size_t n_faces() const override { return m_out.polygons.size(); }
  size_t n_edges() const override { return 0; }

 private:
  RawMesh& m_out;
};

/// OpenMesh reports reader problems on its own log streams; capture them for the error text.
class CapturedLog {
 public:
  CapturedLog() : m_oldErr(std::cerr.rdbuf(m_text.rdbuf())) {}
  ~CapturedLog() { std::cerr.rdbuf(m_oldErr); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  std::string firstLine() const {
    std::string line;
    std::istringstream in(m_text.str());
    while (std::getline(in, line))
      if (!line.empty()) return line;
    return {};
  }

 private:
  std::ostringstream m_text;
  std::streambuf* m_oldErr;
};

/// OpenMesh's text readers parse numbers with iostreams, which stop at "nan" or "inf" and then
/// read the rest of the file out of step. So text PLY, OFF and STL files are scanned first:
/// a non-finite number in the data is reported with its line. Binary files need no scan (their
/// NaNs arrive as floats and validation names the vertex).
Result<void> scanTextForNonFinite(const std::filesystem::path& path, const std::string& ext) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return {};
  bool inData = ext == ".off";  // OFF: data starts after the first line
  bool isText = true;
  if (ext == ".stl") isText = line.rfind("solid", 0) == 0;
  int lineNo = 1;
  while (isText && std::getline(in, line)) {
    ++lineNo;
    std::istringstream tokens(line);
    std::string token;
    if (ext == ".ply" && !inData) {
      tokens >> token;
      if (token == "format" && (tokens >> token) && token != "ascii") return {};  // binary PLY
      inData = token == "end_header";
      continue;
    }
    if (ext == ".stl") {
      if (!(tokens >> token) || token != "vertex") continue;
    }
    while (tokens >> token) {
      std::string lower(token.size(), ' ');
      std::transform(token.begin(), token.end(), lower.begin(),
                     [](unsigned char c) { return char(std::tolower(c)); });
      const auto start = lower.find_first_not_of("+-");
      if (start != std::string::npos &&
          (lower.compare(start, 3, "nan") == 0 || lower.compare(start, 3, "inf") == 0)) {
        return Error{path.string() + ":" + std::to_string(lineNo) + ": non-finite number '" + token +
                     "'; replace NaN/Inf coordinates with real numbers"};
      }
    }
  }
  return {};
}

/// Bounded memory on bad input: the counts an OFF or binary STL header declares are checked
/// against the file size before a reader allocates for them, so a header declaring 10^12
/// vertices fails at once. Each OFF vertex or face takes at least 5 bytes ("0 0 0", binary:
/// 12); each binary STL triangle exactly 50 after the 84-byte header.
Result<void> checkDeclaredCounts(const std::filesystem::path& path, const std::string& ext) {
  std::error_code ec;
  const auto size = std::uint64_t(std::filesystem::file_size(path, ec));
  if (ec) return {};
  std::ifstream in(path, std::ios::binary);
  if (ext == ".stl") {
    char head[84] = {};
    if (!in.read(head, 84)) return {};
    std::uint32_t n = 0;
    std::memcpy(&n, head + 80, 4);  // little-endian, as the format says
    if (std::uint64_t(84) + 50ull * n == size) return {};
    if (std::string_view(head, 5) == "solid") return {};  // ASCII STL
    return Error{path.string() + ": binary STL header declares " + std::to_string(n) +
                 " triangles, but the file has room for " + std::to_string(size < 84 ? 0 : (size - 84) / 50) +
                 "; the file is truncated or not an STL"};
  }
  // OFF: the first line with content after the "OFF" keyword holds "vertices faces edges".
  std::string line;
  std::getline(in, line);
  int lineNo = 1;
  const std::string keyword = line;
  const bool keywordOnly = line.find_first_of("0123456789") == std::string::npos;
  // The next line with content (not blank, not a comment); false at the end.
  auto nextContent = [&in, &lineNo](std::string& text) {
    while (std::getline(in, text)) {
      ++lineNo;
      const auto start = text.find_first_not_of(" \t\r");
      if (start != std::string::npos && text[start] != '#') return true;
    }
    return false;
  };
  if (keywordOnly) {
    nextContent(line);
  } else {
    line = line.substr(line.find_first_of("0123456789"));
  }
  // The counts may also be split over lines (the format is whitespace-separated; found by the
  // OFF fuzz target: a vertex count alone on its line escaped this check).
  std::istringstream counts(line);
  double vertices = 0, faces = 0;
  if (!(counts >> vertices)) return {};  // OpenMesh's reader reports the bad header
  bool split = false;                    // the counts went on over a line: the lines below are not checked
  if (!(counts >> faces)) {
    split = true;
    if (!(in >> faces)) faces = 0;
  }
  // OpenMesh's reader takes the counts from the line after the keyword line whatever that line
  // holds, and reads them as unsigned ("-01" is 4294967295 faces: the OFF fuzz target found it
  // looping); so where the keyword line holds digits, the next line must pass as counts too.
  if (!keywordOnly) {
    std::streampos back = in.tellg();
    const int backLine = lineNo;
    std::string following;
    double v2 = 0, f2 = 0;
    if (nextContent(following) && std::sscanf(following.c_str(), "%lf %lf", &v2, &f2) >= 1 &&
        (v2 < 0 || f2 < 0 || (v2 + f2) * 5.0 > double(size))) {
      vertices = v2;
      faces = f2;
    }
    in.clear();
    in.seekg(back);
    lineNo = backLine;
  }
  if (vertices < 0 || faces < 0 || (vertices + faces) * 5.0 > double(size)) {
    // Printed as doubles: a count beyond 2^63 must not be converted to an integer (UB).
    auto count = [](double n) {
      char text[40];
      std::snprintf(text, sizeof text, "%.0f", n);
      return std::string(text);
    };
    return Error{path.string() + ": the OFF header declares " + count(vertices) + " vertices and " +
                 count(faces) + " faces, more than a " + std::to_string(size) +
                 "-byte file can hold; fix the counts on the header line"};
  }
  // Each ASCII face line starts with its corner count, which OpenMesh's reader trusts and
  // allocates for (found by the OFF fuzz target: "39999999999 0 2012 3" took 2 GiB). A polygon
  // with more corners than the mesh has vertices is not one. Binary OFF and the dimension
  // variants (nOFF, 4OFF) are left to the reader.
  if (split || keyword.find("BINARY") != std::string::npos ||
      keyword.find_first_of("n4") < keyword.find("OFF"))
    return {};
  for (double v = 0; v < vertices && nextContent(line); ++v) {
  }
  for (double f = 0; f < faces && nextContent(line); ++f) {
    double corners = 0;
    if (std::sscanf(line.c_str(), "%lf", &corners) != 1) return {};  // the reader reports it
    if (corners < 0 || corners > vertices) {
      char text[40];
      std::snprintf(text, sizeof text, "%.0f", corners);
      return Error{path.string() + ":" + std::to_string(lineNo) + ": a face declares " + text +
                   " corners, but the mesh has " + std::to_string(std::uint64_t(vertices)) +
                   " vertices; fix the face's corner count"};
    }
  }
  return {};
}

/// ASCII OFF as OpenMesh's reader takes it: the keyword line, then unsigned counts and values
/// read word by word across lines ("-01" is 4294967295; a glued "10-0" shifts every later read),
/// each face's corner count an unsigned it allocates for, and on a failed stream the previous
/// count again for every face left (found by the OFF fuzz target: OpenMesh adding faces until
/// the timeout). So the same reads run here first, with the same standard library: a corner
/// count beyond the vertices, or data that breaks before the last face, is refused.
Result<void> checkOffAsOpenMeshReadsIt(const std::filesystem::path& path, std::uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string header;
  std::getline(in, header);
  const auto off = header.find("OFF");
  if (off == std::string::npos) return {};
  const std::string prefix = header.substr(0, off);  // [ST][C][N]: the reader's options
  const bool normals = prefix.find('N') != std::string::npos, colours = prefix.find('C') != std::string::npos;
  if (header.find("BINARY") != std::string::npos) {
    // Binary: little-endian uint32 counts, 12 bytes a vertex (+12 normal, +12 colour as three
    // ints, +8 texture coordinates), each face a uint32 corner count and its indices.
    const auto word = [&in]() -> std::optional<std::uint32_t> {
      std::uint8_t b[4];
      if (!in.read(reinterpret_cast<char*>(b), 4)) return std::nullopt;
      return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
             std::uint32_t(b[3]) << 24;
    };
    const auto nv = word(), nf = word(), ne = word();
    if (!nv || !nf || !ne)  // OpenMesh would go on with counts it never read
      return Error{path.string() +
                   ": the binary OFF header ends before its three counts; the file is truncated"};
    const std::uint64_t vertexBytes =
        12 + (normals ? 12 : 0) + (colours ? 12 : 0) + (prefix.find("ST") == 0 ? 8 : 0);
    if (*nv * vertexBytes + std::uint64_t(*nf) * 4 > size)
      return Error{path.string() + ": the binary OFF header declares " + std::to_string(*nv) +
                   " vertices and " + std::to_string(*nf) + " faces, more than a " + std::to_string(size) +
                   "-byte file can hold; fix the counts or the truncated file"};
    in.seekg(std::streamoff(*nv * vertexBytes), std::ios::cur);
    for (std::uint32_t f = 0; f < *nf; ++f) {
      const auto corners = word();
      if (!corners || *corners > *nv)
        return Error{path.string() + ": binary OFF face " + std::to_string(f + 1) + " of " +
                     std::to_string(*nf) +
                     (corners ? " declares " + std::to_string(*corners) + " corners, but the mesh has " +
                                    std::to_string(*nv) + " vertices"
                              : " is past the end of the file") +
                     "; fix the file"};
      in.seekg(std::streamoff(*corners) * 4, std::ios::cur);
    }
    return {};
  }
  unsigned vertices = 0, faces = 0, edges = 0;
  if (!(in >> vertices >> faces))  // OpenMesh would go on with its counts uninitialised
    return Error{path.string() +
                 ": no vertex and face counts after the OFF line; add them ('vertices faces edges')"};
  in >> edges;
  if ((std::uint64_t(vertices) + faces) * 5 > size)
    return Error{path.string() + ": the OFF counts read as " + std::to_string(vertices) + " vertices and " +
                 std::to_string(faces) + " faces, more than a " + std::to_string(size) +
                 "-byte file can hold; fix the counts after the OFF line"};
  std::string rest;
  for (unsigned v = 0; v < vertices && !in.eof(); ++v) {
    float x = 0;
    in >> x >> x >> x;
    if (normals) in >> x >> x >> x;
    std::getline(in, rest);
  }
  for (unsigned f = 0; f < faces; ++f) {
    unsigned corners = 0, index = 0;
    if (!(in >> corners))
      return Error{path.string() + ": the OFF data breaks before face " + std::to_string(f + 1) + " of " +
                   std::to_string(faces) + " (read word by word, as OpenMesh does); fix the file"};
    if (corners > vertices)
      return Error{path.string() + ": OFF face " + std::to_string(f + 1) + " declares " +
                   std::to_string(corners) + " corners, but the mesh has " + std::to_string(vertices) +
                   " vertices (read word by word, as OpenMesh does); fix the face"};
    for (unsigned k = 0; k < corners; ++k)
      in >> index;
    if (colours) std::getline(in, rest);
  }
  return {};
}

/// A VTK surface (legacy POLYDATA or XML PolyData, read by the volume module's VTK adapter).
Result<RawMesh> readVtk(const std::filesystem::path& path) {
  auto surface = volume::readVtkSurface(path);
  if (!surface) return surface.error();
  RawMesh raw;
  raw.points.reserve(surface->points.size());
  for (const auto& p : surface->points)
    raw.points.push_back({float(p[0]), float(p[1]), float(p[2])});
  // Ids beyond int become -1, which the loader reports as out of range.
  const auto toInts = [](const std::vector<std::int64_t>& cell) {
    std::vector<int> out(cell.size());
    std::transform(cell.begin(), cell.end(), out.begin(),
                   [](std::int64_t id) { return id >= 0 && id <= 2147483647 ? int(id) : -1; });
    return out;
  };
  for (const auto& cell : surface->polygons) {
    raw.polygons.push_back(toInts(cell));
    raw.cornerUvs.emplace_back();
  }
  for (const auto& strip : surface->strips)
    appendStripTriangles(toInts(strip), 0, raw);
  if (surface->ignoredCells > 0)
    raw.notes.push_back(path.string() + ": ignored " + std::to_string(surface->ignoredCells) +
                        " VERTICES and LINES cells (a surface mesh keeps POLYGONS and TRIANGLE_STRIPS)");
  return raw;
}

}  // namespace

Result<RawMesh> readRawMesh(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return Error{"cannot open mesh '" + path.string() + "': no such file; check the path"};
  }
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl" && ext != ".vtk" && ext != ".vtp") {
    return Error{"cannot read mesh '" + path.string() + "': unsupported extension '" + ext +
                 "'; give an .obj, .ply, .off, .stl or VTK surface (.vtk POLYDATA, .vtp) file"};
  }
  if (ext == ".obj") return readObj(path);
  if (ext == ".vtk" || ext == ".vtp") return readVtk(path);
  if (auto scan = scanTextForNonFinite(path, ext); !scan) return scan.error();
  if (ext == ".ply") return readPly(path);
  if (auto counts = checkDeclaredCounts(path, ext); !counts) return counts.error();
  if (ext == ".off") {
    std::error_code sizeError;
    const auto size = std::uint64_t(std::filesystem::file_size(path, sizeError));
    if (auto stream = checkOffAsOpenMeshReadsIt(path, sizeError ? 0 : size); !stream) return stream.error();
  }
  RawMesh raw;
  RawImporter importer(raw);
  OpenMesh::IO::Options options = OpenMesh::IO::Options::FaceTexCoord | OpenMesh::IO::Options::VertexTexCoord;
  bool ok = false;
  std::string log;
  {
    CapturedLog captured;
    ok = OpenMesh::IO::IOManager().read(path.string(), importer, options);
    log = captured.firstLine();
  }
  if (!ok) {
    return Error{"cannot parse mesh '" + path.string() + "'" + (log.empty() ? "" : " (" + log + ")") +
                 "; check that the file is a valid " + ext.substr(1) + " file"};
  }
  // The readers report per-face texture coordinates only where the file has them.
  if (!options.vertex_has_texcoord()) raw.vertexUvs.clear();
  return raw;
}

}  // namespace tissue::mesh::detail
