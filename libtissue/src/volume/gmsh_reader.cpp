// A small reader of Gmsh .msh files: ASCII v1 ($NOD/$ELM), v2 and v4.1 ($Nodes/$Elements).
// Hand-written because Debian packages no small library for it (docs/DECISIONS.md). Only node
// coordinates and 4-node tets (element type 4) are kept; other elements are counted.
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "raw_volume.h"

namespace tissue::volume::detail {
namespace {

constexpr long kGmshTet = 4;  ///< Gmsh element type of the 4-node tetrahedron

/// The file's lines with a cursor; errors name the file and the line (1-based).
class Lines {
 public:
  Lines(std::string file, std::vector<std::string> lines)
      : m_file(std::move(file)), m_lines(std::move(lines)) {}

  bool atEnd() const { return m_next >= m_lines.size(); }
  /// The next line with any content, as whitespace-separated tokens; empty at the end.
  std::vector<std::string_view> next() {
    while (m_next < m_lines.size()) {
      std::vector<std::string_view> tokens = split(m_lines[m_next++]);
      if (!tokens.empty()) return tokens;
    }
    return {};
  }
  Error error(const std::string& what) const {
    return Error{m_file + ":" + std::to_string(m_next) + ": " + what};
  }

 private:
  static std::vector<std::string_view> split(std::string_view s) {
    std::vector<std::string_view> out;
    std::size_t k = 0;
    while (k < s.size()) {
      while (k < s.size() && (s[k] == ' ' || s[k] == '\t' || s[k] == '\r'))
        ++k;
      const std::size_t start = k;
      while (k < s.size() && s[k] != ' ' && s[k] != '\t' && s[k] != '\r')
        ++k;
      if (k > start) out.push_back(s.substr(start, k - start));
    }
    return out;
  }

  std::string m_file;
  std::vector<std::string> m_lines;
  std::size_t m_next = 0;
};

bool toInt(std::string_view s, long& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}
bool toDouble(std::string_view s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

/// Reads integers token[first..] of `tokens`; false on a malformed one.
bool ints(const std::vector<std::string_view>& tokens, std::size_t first, std::vector<long>& out) {
  out.clear();
  for (std::size_t k = first; k < tokens.size(); ++k) {
    long v = 0;
    if (!toInt(tokens[k], v)) return false;
    out.push_back(v);
  }
  return true;
}

/// State shared by the versions: node tags to indices, and the result.
struct Builder {
  RawVolume raw;
  std::unordered_map<long, std::int64_t> index;  ///< node tag -> 0-based index
  std::size_t elements = 0;                      ///< elements seen, for 1-based numbering

  Result<void> addNode(Lines& in, long tag, std::string_view x, std::string_view y, std::string_view z) {
    std::array<double, 3> p{};
    if (!toDouble(x, p[0]) || !toDouble(y, p[1]) || !toDouble(z, p[2]))
      return in.error("node " + std::to_string(tag) + " has a coordinate that is not a number");
    if (!index.emplace(tag, static_cast<std::int64_t>(raw.points.size())).second)
      return in.error("node tag " + std::to_string(tag) + " is defined twice; give each node one tag");
    raw.points.push_back(p);
    return {};
  }
  /// One element of `type` with node tags `nodes`; tets are kept, others counted.
  Result<void> addElement(Lines& in, long type, const std::vector<long>& nodes) {
    ++elements;
    if (type != kGmshTet) {
      ++raw.ignoredCells;
      return {};
    }
    if (nodes.size() != 4)
      return in.error("element " + std::to_string(elements) + " is a tet (type 4) with " +
                      std::to_string(nodes.size()) + " nodes; a tet has 4");
    RawTet tet;
    tet.element = elements;
    for (std::size_t k = 0; k < 4; ++k) {
      auto it = index.find(nodes[k]);
      if (it == index.end())
        return in.error("element " + std::to_string(elements) + " refers to node tag " +
                        std::to_string(nodes[k]) + ", which the nodes section does not define");
      tet.v[k] = it->second;
    }
    raw.tets.push_back(tet);
    return {};
  }
};

/// Reads the count line of a v1/v2 section.
Result<long> countLine(Lines& in, const char* section) {
  const auto tokens = in.next();
  long n = 0;
  if (tokens.size() != 1 || !toInt(tokens[0], n) || n < 0)
    return in.error(std::string("expected the number of entries after ") + section);
  return n;
}

/// v1 $NOD / v2 $Nodes: "tag x y z" per line.
Result<void> readNodesV12(Lines& in, Builder& b, const char* section) {
  auto n = countLine(in, section);
  if (!n) return n.error();
  for (long k = 0; k < *n; ++k) {
    const auto t = in.next();
    long tag = 0;
    if (t.size() < 4 || !toInt(t[0], tag)) return in.error("expected a node line: tag x y z");
    if (auto ok = b.addNode(in, tag, t[1], t[2], t[3]); !ok) return ok;
  }
  return {};
}

/// v1 $ELM: "number type physical elementary nodeCount nodes..."; v2 $Elements:
/// "number type tagCount tags... nodes...".
Result<void> readElementsV12(Lines& in, Builder& b, bool v1) {
  auto n = countLine(in, v1 ? "$ELM" : "$Elements");
  if (!n) return n.error();
  std::vector<long> v;
  for (long k = 0; k < *n; ++k) {
    if (!ints(in.next(), 0, v) || v.size() < 3) return in.error("expected an element line of integers");
    const std::size_t first = v1 ? 5 : 3 + static_cast<std::size_t>(std::max(0L, v[2]));
    if (v.size() < first || (v1 && v.size() != first + static_cast<std::size_t>(std::max(0L, v[4]))))
      return in.error("element line has the wrong number of entries");
    if (auto ok = b.addElement(in, v[1], std::vector<long>(v.begin() + static_cast<long>(first), v.end()));
        !ok)
      return ok;
  }
  return {};
}

/// v4.1 $Nodes: blocks of "dim tag parametric n", then n tags, then n coordinate lines.
Result<void> readNodesV4(Lines& in, Builder& b) {
  std::vector<long> head;
  if (!ints(in.next(), 0, head) || head.size() != 4) return in.error("expected the $Nodes header of v4.1");
  for (long block = 0; block < head[0]; ++block) {
    std::vector<long> bh;
    if (!ints(in.next(), 0, bh) || bh.size() != 4) return in.error("expected a node block header");
    std::vector<long> tags(static_cast<std::size_t>(std::max(0L, bh[3])));
    for (auto& tag : tags) {
      const auto t = in.next();
      if (t.size() != 1 || !toInt(t[0], tag)) return in.error("expected a node tag");
    }
    for (long tag : tags) {
      const auto t = in.next();
      if (t.size() < 3) return in.error("expected node coordinates x y z");
      if (auto ok = b.addNode(in, tag, t[0], t[1], t[2]); !ok) return ok;
    }
  }
  return {};
}

/// v4.1 $Elements: blocks of "dim tag type n", then n lines "elementTag nodeTags...".
Result<void> readElementsV4(Lines& in, Builder& b) {
  std::vector<long> head, v;
  if (!ints(in.next(), 0, head) || head.size() != 4) return in.error("expected the $Elements header of v4.1");
  for (long block = 0; block < head[0]; ++block) {
    std::vector<long> bh;
    if (!ints(in.next(), 0, bh) || bh.size() != 4) return in.error("expected an element block header");
    for (long k = 0; k < bh[3]; ++k) {
      if (!ints(in.next(), 0, v) || v.empty()) return in.error("expected an element line of integers");
      if (auto ok = b.addElement(in, bh[2], std::vector<long>(v.begin() + 1, v.end())); !ok) return ok;
    }
  }
  return {};
}

/// Reads $MeshFormat and returns the major version (2 or 4); fails on binary or 4.0.
Result<int> readFormat(Lines& in) {
  const auto t = in.next();
  if (t.size() < 2) return in.error("expected '$MeshFormat' version, file type and data size");
  if (t[1] != "0")
    return in.error("binary .msh is not supported; save the mesh from Gmsh as ASCII (msh2 or msh4.1)");
  if (t[0].substr(0, 2) == "2.") return 2;
  if (t[0] == "4.1") return 4;
  return in.error("Gmsh format version " + std::string(t[0]) + " is not supported; save as ASCII 2.2 or 4.1");
}

}  // namespace

Result<RawVolume> readGmsh(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) return Error{path.string() + ": cannot open the file; check the path"};
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);)
    lines.push_back(std::move(line));
  Lines in(path.string(), std::move(lines));
  Builder b;
  int version = 1;
  bool sawNodes = false;
  // Sections in any order; unknown ones ($Entities, $PhysicalNames, ...) are skipped.
  for (auto t = in.next(); !t.empty(); t = in.next()) {
    Result<void> ok;
    if (t[0] == "$MeshFormat") {
      auto v = readFormat(in);
      if (!v) return v.error();
      version = *v;
    } else if (t[0] == "$NOD" || t[0] == "$Nodes") {
      ok = version == 4 ? readNodesV4(in, b) : readNodesV12(in, b, t[0] == "$NOD" ? "$NOD" : "$Nodes");
      sawNodes = true;
    } else if (t[0] == "$ELM" || t[0] == "$Elements") {
      if (!sawNodes) return in.error("the elements come before the nodes; a .msh lists nodes first");
      ok = version == 4 ? readElementsV4(in, b) : readElementsV12(in, b, t[0] == "$ELM");
    }
    if (!ok) return ok.error();
  }
  if (!sawNodes) return Error{path.string() + ": no $Nodes (or $NOD) section; is this a Gmsh mesh?"};
  return std::move(b.raw);
}

}  // namespace tissue::volume::detail
