// loadTetMesh: picks the reader by extension, then validates what it read.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>

#include "raw_volume.h"
#include "tissue/volume/tet_mesh.h"
#include "tissue/volume/vtk_surface.h"

namespace tissue::volume {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// Longest edge of a tet (mm), the scale of the degeneracy test.
double longestEdge(std::span<const Float3> p, const Tet& t) {
  double longest = 0.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      const Float3& u = p[t[static_cast<std::size_t>(a)]];
      const Float3& w = p[t[static_cast<std::size_t>(b)]];
      const double dx = double{u.x} - double{w.x}, dy = double{u.y} - double{w.y},
                   dz = double{u.z} - double{w.z};
      longest = std::max(longest, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return longest;
}

/// Checks and converts one tet; re-orients an inverted one. `where` names the file.
Result<Tet> checkTet(const detail::RawTet& raw, std::span<const Float3> positions, const std::string& where,
                     bool& reoriented) {
  const std::string element = where + ": tet element " + std::to_string(raw.element);
  Tet t{};
  for (std::size_t k = 0; k < 4; ++k) {
    if (raw.v[k] < 0 || static_cast<std::size_t>(raw.v[k]) >= positions.size())
      return Error{element + " refers to vertex " + std::to_string(raw.v[k] + 1) +
                   " (1-based), but there are " + std::to_string(positions.size()) +
                   " vertices; fix the connectivity"};
    t[k] = static_cast<std::uint32_t>(raw.v[k]);
  }
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b)
      if (t[a] == t[b])
        return Error{element + " repeats vertex " + std::to_string(t[a] + 1) +
                     " (1-based); a tet needs four distinct vertices"};
  // Degenerate: |6 V| tiny against the cube of the longest edge (a flat or collapsed tet).
  const double v = signedTetVolume(positions, t);
  const double l = longestEdge(positions, t);
  if (!(std::abs(6.0 * v) > 1e-9 * l * l * l))
    return Error{element + " has zero volume (its four vertices are coplanar); remove or re-mesh it"};
  reoriented = v < 0.0;
  if (reoriented) std::swap(t[2], t[3]);
  return t;
}

/// Validates `raw` into a TetMesh; the error names `where` and the element, 1-based.
Result<TetMesh> validate(const detail::RawVolume& raw, const std::string& where, float scale,
                         TetLoadReport& report) {
  TetMesh mesh;
  mesh.positions.reserve(raw.points.size());
  for (std::size_t p = 0; p < raw.points.size(); ++p) {
    const auto& q = raw.points[p];
    const double s = scale;
    const Float3 f{float(q[0] * s), float(q[1] * s), float(q[2] * s)};
    if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z))
      return Error{where + ": vertex " + std::to_string(p + 1) +
                   " has a coordinate that is not finite (NaN or Inf); fix the file"};
    mesh.positions.push_back(f);
  }
  report.ignoredCells = raw.ignoredCells;
  if (raw.tets.empty())
    return Error{where + ": no tetrahedra (found " + std::to_string(raw.ignoredCells) +
                 " other cells); give a tetrahedral volume mesh"};
  std::vector<char> used(mesh.positions.size(), 0);
  mesh.tets.reserve(raw.tets.size());
  for (const auto& rt : raw.tets) {
    bool reoriented = false;
    auto t = checkTet(rt, mesh.positions, where, reoriented);
    if (!t) return t.error();
    report.reorientedTets += reoriented ? 1 : 0;
    for (std::uint32_t v : *t)
      used[v] = 1;
    mesh.tets.push_back(*t);
  }
  report.unreferencedVertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  if (report.ignoredCells > 0)
    report.warnings.push_back(where + ": ignored " + std::to_string(report.ignoredCells) +
                              " cells that are not 4-node tets");
  if (report.reorientedTets > 0)
    report.warnings.push_back(where + ": re-oriented " + std::to_string(report.reorientedTets) +
                              " inverted tets");
  if (report.unreferencedVertices > 0)
    report.warnings.push_back(where + ": " + std::to_string(report.unreferencedVertices) +
                              " vertices belong to no tet");
  return mesh;
}

}  // namespace

namespace detail {

VtkContent sniffVtk(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const auto first = head.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return VtkContent::Unknown;
  if (head[first] == '<') {
    const auto type = head.find("type=\"");
    if (type == std::string::npos) return VtkContent::Unknown;
    const std::string value = head.substr(type + 6, head.find('"', type + 6) - (type + 6));
    if (value == "UnstructuredGrid") return VtkContent::XmlGrid;
    if (value == "PolyData") return VtkContent::XmlSurface;
    return VtkContent::Unknown;
  }
  std::string upper(head.size(), ' ');
  std::transform(head.begin(), head.end(), upper.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  const auto dataset = upper.find("\nDATASET");
  if (dataset == std::string::npos) return VtkContent::Unknown;
  // "\nDATASET" may end the 4 kB read: substr past the end would throw (the VTK fuzzer).
  const std::size_t from = std::min(dataset + 9, upper.size());
  std::string kind = upper.substr(from, upper.find('\n', dataset + 1) - from);
  kind.erase(0, kind.find_first_not_of(" \t"));
  kind.erase(kind.find_last_not_of(" \t\r") + 1);
  if (kind == "POLYDATA") return VtkContent::LegacySurface;
  if (kind == "UNSTRUCTURED_GRID") return VtkContent::LegacyGrid;
  return VtkContent::Unknown;
}

namespace {

/// An integer as C++ streams read it (VTK's `>>`): an optional sign, then digits only.
bool isInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && std::isdigit(static_cast<unsigned char>(token[1])))
    token.remove_prefix(1);  // from_chars takes no '+'; the stream does ("CELLS 2 +0": the VTK fuzzer)
  long long v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  return ec == std::errc() && end == token.data() + token.size();
}

/// A coordinate as C++ streams read it (VTK's `>>`): an optional sign, digits, a point, an
/// exponent; no "nan" or "inf", which the stream refuses.
bool isNumber(std::string_view token) {
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  if (token.empty() || !(std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '.')) return false;
  double v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  return ec == std::errc() && end == token.data() + token.size();
}

/// Text legacy VTK: each cell section must hold the integers its header declares. VTK 9.1's
/// vtkPolyDataReader crashes (a null stream after it closes the file) on a cell section that
/// ends early or holds a non-number, so the sections are counted before VTK reads the file.
Result<void> checkTextCellSections(const std::filesystem::path& path, const std::string& text) {
  std::size_t pos = 0, line = 1;
  const auto next = [&]() -> std::string_view {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
      line += text[pos++] == '\n' ? 1 : 0;
    const std::size_t start = pos;
    while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos])))
      ++pos;
    return std::string_view(text).substr(start, pos - start);
  };
  const auto needIntegers = [&](std::uint64_t n, const std::string& section, std::size_t at) -> Result<void> {
    for (std::uint64_t k = 0; k < n; ++k) {
      const auto token = next();
      if (!isInteger(token))
        return Error{path.string() + ":" + std::to_string(at) + ": " + section + " declares " +
                     std::to_string(n) + " integers, but entry " + std::to_string(k + 1) +
                     (token.empty() ? " is past the end of the file" : " is '" + std::string(token) + "'") +
                     "; the file is truncated or damaged"};
    }
    return {};
  };
  // A section's count must be a whole number >= 0: VTK's stream reads a number's prefix ("2x"
  // as 2, then "x" as the next word), so anything else is refused here, not left to VTK.
  const auto count = [&](std::string_view token, const std::string& section,
                         std::size_t at) -> Result<std::uint64_t> {
    long long n = -1;
    if (isInteger(token)) {
      const auto digits = token.substr(token[0] == '+' ? 1 : 0);
      std::from_chars(digits.data(), digits.data() + digits.size(), n);
    }
    if (n < 0)
      return Error{path.string() + ":" + std::to_string(at) + ": " + section + " count '" +
                   std::string(token) + "' is not a whole number >= 0; fix the section header"};
    return std::uint64_t(n);
  };
  for (auto token = next(); !token.empty(); token = next()) {
    // VTK matches its keywords by a case-blind prefix (strncmp of the lower-cased word), so
    // "CELLSPOINTS" is a CELLS section to it (the VTK fuzzer); the same rule here.
    std::string upper(token);
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    std::string section;
    for (const char* keyword : {"CELL_TYPES", "CELLS", "VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"})
      if (upper.rfind(keyword, 0) == 0) {
        section = keyword;
        break;
      }
    if (upper.rfind("POINTS", 0) == 0) {
      // A coordinate that does not read as a number makes VTK go on reading keywords from
      // inside it ("10CELLS0 10 0" turned into CELLS 10 0, a SIGSEGV; the VTK fuzzer).
      const std::size_t at = line;
      const auto declared = count(next(), "POINTS", at);
      if (!declared) return declared.error();
      const std::uint64_t n = *declared;
      next();  // the type
      const std::uint64_t values = std::min<std::uint64_t>(n, text.size()) * 3;
      for (std::uint64_t k = 0; k < values; ++k) {
        const auto value = next();
        if (value.empty()) break;  // truncated: VTK reports it, with nothing left to misread
        if (!isNumber(value))
          return Error{path.string() + ":" + std::to_string(at) + ": POINTS declares " + std::to_string(n) +
                       " points, but coordinate " + std::to_string(k + 1) + " is '" + std::string(value) +
                       "'; the file is damaged"};
      }
      continue;
    }
    if (section.empty()) continue;
    const std::size_t at = line;
    const auto first = count(next(), section, at);
    if (!first) return first.error();
    const std::uint64_t a = *first;
    if (section == "CELL_TYPES") {
      if (auto ok = needIntegers(a, section, at); !ok) return ok;
      continue;
    }
    const auto second = count(next(), section, at);
    if (!second) return second.error();
    const std::uint64_t b = *second;
    const std::size_t save = pos, saveLine = line;
    if (next() == "OFFSETS") {  // the version 5 layout: OFFSETS type, a ints, CONNECTIVITY type, b ints
      next();
      if (auto ok = needIntegers(std::uint64_t(a), section + " OFFSETS", at); !ok) return ok;
      if (next() != "CONNECTIVITY") continue;  // VTK reports it
      next();
      if (auto ok = needIntegers(std::uint64_t(b), section + " CONNECTIVITY", at); !ok) return ok;
      continue;
    }
    pos = save;
    line = saveLine;
    if (auto ok = needIntegers(std::uint64_t(b), section, at); !ok) return ok;
    // The legacy layout: a cells, each "n id_1 .. id_n", b integers in all. VTK 9.1's readers
    // crash when the cells do not fill the b integers exactly ("CELLS 240 0": a null buffer
    // written; found by the VTK fuzzer), so the cells are walked too, over the integers counted.
    const std::size_t end = pos, endLine = line;
    pos = save;
    line = saveLine;
    const auto total = std::uint64_t(b);
    std::uint64_t used = 0;
    for (std::uint64_t c = 0; c < std::uint64_t(a); ++c) {
      const long long n = used < total ? std::stoll(std::string(next())) : -1;
      if (n < 0 || std::uint64_t(n) >= total - used)
        return Error{path.string() + ":" + std::to_string(at) + ": " + section + " declares " +
                     std::to_string(a) + " cells in " + std::to_string(b) + " integers, but cell " +
                     std::to_string(c + 1) + " does not fit in them; fix the counts"};
      for (long long k = 0; k < n; ++k)
        next();
      used += 1 + std::uint64_t(n);
    }
    if (used != total)
      return Error{path.string() + ":" + std::to_string(at) + ": " + section + " declares " +
                   std::to_string(a) + " cells in " + std::to_string(b) + " integers, but its cells hold " +
                   std::to_string(used) + "; fix the counts"};
    pos = end;
    line = endLine;
  }
  return {};
}

}  // namespace

Result<void> checkLegacyVtkCounts(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::uint64_t(std::filesystem::file_size(path, ec));
  if (ec) return {};
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool ascii = false, formatRead = false;
  for (int k = 0; k < 8 && std::getline(in, line); ++k) {
    // The format keyword is the first word after the title: VTK skips blank lines to reach it
    // ("Version 3\x0e0", a binary title, a blank line, then "ASCII": the VTK fuzzer's crash,
    // which went past this check when it looked at the third line only).
    if (k >= 2 && !formatRead && line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (k >= 2 && !formatRead) {  // VTK lower-cases it first: "ASCIi" is a text file to it
      formatRead = true;
      std::string lower = line.substr(line.find_first_not_of(" \t\r"), 5);
      std::transform(lower.begin(), lower.end(), lower.begin(),
                     [](unsigned char c) { return char(std::tolower(c)); });
      ascii = lower == "ascii";
    }
    if (line.rfind("POINTS", 0) != 0) continue;
    double n = 0;
    if (std::sscanf(line.c_str() + 6, "%lf", &n) != 1) break;  // the text check below refuses it
    // Each point takes at least 6 bytes as text ("0 0 0 ") and 12 in binary floats.
    if (n < 0 || n * 6.0 > double(size)) {
      std::ostringstream declared;  // not via an integer: 1e29 does not fit one (the VTK fuzzer, UBSan)
      declared << std::setprecision(15) << std::max(0.0, n);
      return Error{path.string() + ":" + std::to_string(k + 1) + ": POINTS declares " + declared.str() +
                   " points, more than a " + std::to_string(size) +
                   "-byte file can hold; fix the count or the truncated file"};
    }
    break;
  }
  if (!ascii) return {};
  in.clear();
  in.seekg(0);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return checkTextCellSections(path, text);
}

Result<void> checkXmlVtkCounts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Appended binary data may be zlib-compressed (at most about 1032:1), so a count is bounded by
  // that many values per byte of the file; a data array's components are a handful (3 for
  // points), 1024 is far beyond any VTK writes for a mesh.
  const double maxCount = 1100.0 * double(text.size()) + 16.0;
  constexpr double kMaxComponents = 1024.0;
  for (std::size_t at = text.find("NumberOf"); at != std::string::npos; at = text.find("NumberOf", at + 8)) {
    const std::size_t eq =
        text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz", at + 8);
    if (eq == std::string::npos || text[eq] != '=' || eq + 1 >= text.size()) continue;  // not an attribute
    const char quote = text[eq + 1];
    if (quote != '"' && quote != '\'') continue;
    const std::size_t end = text.find(quote, eq + 2);
    const std::string name = text.substr(at, eq - at);
    const std::string value =
        text.substr(eq + 2, end == std::string::npos ? 40 : std::min<std::size_t>(end - eq - 2, 40));
    const bool digits = !value.empty() && value.size() <= 18 &&
                        value.find_first_not_of("0123456789") == std::string::npos &&
                        end != std::string::npos;
    const double n = digits ? std::stod(value) : -1.0;
    const double bound = name == "NumberOfComponents" ? kMaxComponents : maxCount;
    if (!digits || n > bound) {
      std::string shown;  // the value as one printable line (it may run over lines: the VTU fuzzer)
      for (const char c : value.substr(0, 40))
        shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
      const auto line = 1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n');
      return Error{path.string() + ":" + std::to_string(line) + ": " + name + "=\"" + shown +
                   (digits ? "\" is more than a " + std::to_string(text.size()) + "-byte file can hold"
                           : "\" is not a whole number") +
                   "; fix the attribute"};
    }
  }
  return {};
}

}  // namespace detail

bool isVtkSurfacePath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".vtp") return true;
  if (ext != ".vtk") return false;
  const auto content = detail::sniffVtk(path);
  return content == detail::VtkContent::LegacySurface || content == detail::VtkContent::XmlSurface;
}

Result<VtkSurface> readVtkSurface(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return Error{path.string() + ": no such file; check the path"};
  const bool xml = lowerExtension(path) == ".vtp" || detail::sniffVtk(path) == detail::VtkContent::XmlSurface;
  if (auto counts = xml ? detail::checkXmlVtkCounts(path) : detail::checkLegacyVtkCounts(path); !counts)
    return counts.error();
  return detail::readVtkPolyData(path, xml);
}

bool isTetMeshPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return (ext == ".vtk" && !isVtkSurfacePath(path)) || ext == ".vtu" || ext == ".msh";
}

Result<TetMesh> loadTetMesh(const std::filesystem::path& path, const TetLoadOptions& options,
                            TetLoadReport* report) {
  if (!(options.scaleToMm > 0.0f) || !std::isfinite(options.scaleToMm))
    return Error{path.string() + ": the scale must be a positive number of mm per file unit"};
  const std::string ext = lowerExtension(path);
  Result<detail::RawVolume> raw = Error{""};
  const auto content = ext == ".vtk" ? detail::sniffVtk(path) : detail::VtkContent::Unknown;
  if (content == detail::VtkContent::LegacySurface || content == detail::VtkContent::XmlSurface)
    return Error{path.string() + ": holds a surface (" +
                 (content == detail::VtkContent::XmlSurface ? "VTK XML PolyData" : "DATASET POLYDATA") +
                 "), not tetrahedra; load it as a surface mesh (tissue-sim mesh-info reads it as one)"};
  if (content == detail::VtkContent::XmlGrid || ext == ".vtu") {
    // XML content under a .vtk name: VTK's XML reader reads it.
    if (auto counts = detail::checkXmlVtkCounts(path); !counts) return counts.error();
    raw = detail::readVtu(path);
  } else if (ext == ".vtk") {
    if (auto counts = detail::checkLegacyVtkCounts(path); !counts) return counts.error();
    raw = detail::readLegacyVtk(path);
  } else if (ext == ".msh")
    raw = detail::readGmsh(path);
  else
    return Error{path.string() + ": unknown volume mesh extension '" + ext + "'; use .vtk, .vtu or .msh"};
  if (!raw) return raw.error();
  TetLoadReport local;
  auto mesh = validate(*raw, path.string(), options.scaleToMm, local);
  if (mesh && report) *report = std::move(local);
  return mesh;
}

}  // namespace tissue::volume
