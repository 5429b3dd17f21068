// A small reader of Gmsh .msh files: ASCII v1 ($NOD/$ELM), v2 (header "2" or "2.x") and v4.1
// ($Nodes/$Elements), and v2 and v4.1 binary (file type 1, with the endianness check int).
// Hand-written because Debian packages no small library for it (docs/DECISIONS.md). Only node
// coordinates and 4-node tets (element type 4) are kept; other elements are counted. Every count
// is checked against the bytes left before anything is allocated for it.
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "raw_volume.h"

namespace tissue::volume::detail {
namespace {

constexpr long kGmshTet = 4;  ///< Gmsh element type of the 4-node tetrahedron

/// The file with a cursor: text lines (as tokens) and, for binary sections, raw values. Errors
/// name the file and the line (1-based) of the last line read.
class Lines {
 public:
  Lines(std::string file, std::string text) : m_file(std::move(file)), m_text(std::move(text)) {}

  /// The next line with any content, as whitespace-separated tokens; empty at the end.
  std::vector<std::string_view> next() {
    while (m_pos < m_text.size()) {
      const std::size_t end = std::min(m_text.find('\n', m_pos), m_text.size());
      const std::string_view line(m_text.data() + m_pos, end - m_pos);
      m_pos = end + 1;
      ++m_line;
      std::vector<std::string_view> tokens = split(line);
      if (!tokens.empty()) return tokens;
    }
    return {};
  }
  /// Moves past the line that starts with `marker` (a section's end); false if there is none.
  bool skipPast(const std::string& marker) {
    for (std::size_t at = m_text.find(marker, m_pos); at != std::string::npos;
         at = m_text.find(marker, at + 1)) {
      if (at != 0 && m_text[at - 1] != '\n') continue;
      m_line += std::size_t(
          std::count(m_text.begin() + std::ptrdiff_t(m_pos), m_text.begin() + std::ptrdiff_t(at), '\n'));
      m_pos = at;
      next();
      return true;
    }
    return false;
  }
  std::size_t remaining() const { return m_pos < m_text.size() ? m_text.size() - m_pos : 0; }

  /// Binary: the byte order of the file differs from this machine's (from the check int).
  void setSwap(bool swap) { m_swap = swap; }
  /// Reads one binary value of `bytes` bytes (4 or 8) as an integer or a double.
  template <class T>
  bool read(T& value) {
    if (remaining() < sizeof(T)) return false;
    unsigned char b[sizeof(T)];
    std::memcpy(b, m_text.data() + m_pos, sizeof(T));
    if (m_swap) std::reverse(b, b + sizeof(T));
    std::memcpy(&value, b, sizeof(T));
    m_pos += sizeof(T);
    return true;
  }

  Error error(const std::string& what) const {
    return Error{m_file + ":" + std::to_string(m_line) + ": " + what};
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
  std::string m_text;
  std::size_t m_pos = 0;
  std::size_t m_line = 0;
  bool m_swap = false;
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

/// What $MeshFormat says.
struct Format {
  int major = 1;         ///< 1 (no $MeshFormat), 2 or 4 (4.1)
  bool binary = false;   ///< file type 1
  std::size_t size = 8;  ///< data size: sizeof(size_t) of the writer in 4.1 (4 or 8)
};

/// Nodes of Gmsh element `type` (the types of Gmsh's manual up to 31), or 0 if unknown: binary
/// elements carry no node count.
std::size_t nodesOfType(long type) {
  static constexpr std::array<std::uint8_t, 32> kNodes = {0,  2,  3,  4,  4, 8, 6,  5,  3,  6, 9,
                                                          10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10,
                                                          12, 15, 15, 21, 4, 5, 6,  20, 35, 56};
  return type >= 0 && type < long(kNodes.size()) ? kNodes[std::size_t(type)] : 0;
}

/// State shared by the versions: node tags to indices, and the result.
struct Builder {
  RawVolume raw;
  std::unordered_map<long, std::int64_t> index;  ///< node tag -> 0-based index
  std::size_t elements = 0;                      ///< elements seen, for 1-based numbering

  Result<void> addNode(Lines& in, long tag, const std::array<double, 3>& p) {
    if (!index.emplace(tag, static_cast<std::int64_t>(raw.points.size())).second)
      return in.error("node tag " + std::to_string(tag) + " is defined twice; give each node one tag");
    raw.points.push_back(p);
    return {};
  }
  Result<void> addNode(Lines& in, long tag, std::string_view x, std::string_view y, std::string_view z) {
    std::array<double, 3> p{};
    if (!toDouble(x, p[0]) || !toDouble(y, p[1]) || !toDouble(z, p[2]))
      return in.error("node " + std::to_string(tag) + " has a coordinate that is not a number");
    return addNode(in, tag, p);
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

/// Bounded memory: `count` entries of at least `bytesEach` bytes must fit in what is left.
Result<void> checkCount(Lines& in, std::uint64_t count, std::uint64_t bytesEach, const char* what) {
  if (bytesEach > 0 && count > in.remaining() / bytesEach)
    return in.error(std::string(what) + " declares " + std::to_string(count) + " entries, more than the " +
                    std::to_string(in.remaining()) +
                    " bytes left can hold; fix the count or the truncated file");
  return {};
}

/// Reads the count line of a v1/v2 section.
Result<long> countLine(Lines& in, const char* section) {
  const auto tokens = in.next();
  long n = 0;
  if (tokens.size() != 1 || !toInt(tokens[0], n) || n < 0)
    return in.error(std::string("expected the number of entries after ") + section);
  return n;
}

/// A binary size_t of the writer (4 or 8 bytes, the format's data size).
bool readSize(Lines& in, const Format& f, std::uint64_t& out) {
  if (f.size == 4) {
    std::uint32_t v = 0;
    if (!in.read(v)) return false;
    out = v;
    return true;
  }
  return in.read(out);
}

Error truncated(Lines& in, const char* section) {
  return in.error(std::string("binary ") + section + " section ends early; the file is truncated");
}

/// v1 $NOD / v2 $Nodes: "tag x y z" per line, or binary (int tag, 3 doubles) per node.
Result<void> readNodesV12(Lines& in, Builder& b, const char* section, const Format& f) {
  auto n = countLine(in, section);
  if (!n) return n.error();
  if (auto ok = checkCount(in, std::uint64_t(*n), f.binary ? 28 : 8, section); !ok) return ok;
  for (long k = 0; k < *n; ++k) {
    if (f.binary) {
      std::int32_t tag = 0;
      std::array<double, 3> p{};
      if (!in.read(tag) || !in.read(p[0]) || !in.read(p[1]) || !in.read(p[2])) return truncated(in, section);
      if (auto ok = b.addNode(in, tag, p); !ok) return ok;
      continue;
    }
    const auto t = in.next();
    long tag = 0;
    if (t.size() < 4 || !toInt(t[0], tag)) return in.error("expected a node line: tag x y z");
    if (auto ok = b.addNode(in, tag, t[1], t[2], t[3]); !ok) return ok;
  }
  return {};
}

/// v2 binary $Elements: blocks of (type, count, tag count), each element its number, tags, nodes.
Result<void> readElementsV2Binary(Lines& in, Builder& b, long n) {
  std::vector<long> nodes;
  for (long done = 0; done < n;) {
    std::int32_t type = 0, follow = 0, tags = 0;
    if (!in.read(type) || !in.read(follow) || !in.read(tags)) return truncated(in, "$Elements");
    const std::size_t count = nodesOfType(type);
    if (count == 0)
      return in.error("binary element type " + std::to_string(type) + " is unknown to this reader");
    if (follow <= 0 || follow > n - done || tags < 0)
      return in.error("binary element block of " + std::to_string(follow) + " elements with " +
                      std::to_string(tags) + " tags does not fit the declared count");
    if (auto ok = checkCount(in, std::uint64_t(follow), 4 * (1 + std::uint64_t(tags) + count), "$Elements");
        !ok)
      return ok;
    for (std::int32_t e = 0; e < follow; ++e, ++done) {
      std::int32_t v = 0;
      for (std::int32_t k = 0; k < 1 + tags; ++k)
        if (!in.read(v)) return truncated(in, "$Elements");
      nodes.assign(count, 0);
      for (auto& node : nodes) {
        if (!in.read(v)) return truncated(in, "$Elements");
        node = v;
      }
      if (auto ok = b.addElement(in, type, nodes); !ok) return ok;
    }
  }
  return {};
}

/// v1 $ELM: "number type physical elementary nodeCount nodes..."; v2 $Elements:
/// "number type tagCount tags... nodes...".
Result<void> readElementsV12(Lines& in, Builder& b, bool v1, const Format& f) {
  auto n = countLine(in, v1 ? "$ELM" : "$Elements");
  if (!n) return n.error();
  if (auto ok = checkCount(in, std::uint64_t(*n), 8, v1 ? "$ELM" : "$Elements"); !ok) return ok;
  if (f.binary) return readElementsV2Binary(in, b, *n);
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

/// v4.1 section header (4 numbers) and block headers (3 ints and a count), text or binary.
bool readHeader4(Lines& in, const Format& f, std::array<std::uint64_t, 4>& h) {
  if (f.binary) {
    for (auto& v : h)
      if (!readSize(in, f, v)) return false;
    return true;
  }
  std::vector<long> v;
  if (!ints(in.next(), 0, v) || v.size() != 4 || *std::min_element(v.begin(), v.end()) < 0) return false;
  std::copy(v.begin(), v.end(), h.begin());
  return true;
}
bool readBlock4(Lines& in, const Format& f, std::array<long, 3>& ints3, std::uint64_t& count) {
  if (f.binary) {
    for (auto& v : ints3) {
      std::int32_t i = 0;
      if (!in.read(i)) return false;
      v = i;
    }
    return readSize(in, f, count);
  }
  std::vector<long> v;
  if (!ints(in.next(), 0, v) || v.size() != 4 || v[3] < 0) return false;
  std::copy(v.begin(), v.begin() + 3, ints3.begin());
  count = std::uint64_t(v[3]);
  return true;
}

/// v4.1 $Nodes: blocks of "dim tag parametric n", then n tags, then n coordinate lines.
Result<void> readNodesV4(Lines& in, Builder& b, const Format& f) {
  std::array<std::uint64_t, 4> head{};
  if (!readHeader4(in, f, head)) return in.error("expected the $Nodes header of v4.1");
  if (auto ok = checkCount(in, head[1], f.binary ? f.size + 24 : 8, "$Nodes"); !ok) return ok;
  if (auto ok = checkCount(in, head[0], f.binary ? 12 + f.size : 8, "$Nodes (entity blocks)"); !ok) return ok;
  for (std::uint64_t block = 0; block < head[0]; ++block) {
    std::array<long, 3> bh{};
    std::uint64_t n = 0;
    if (!readBlock4(in, f, bh, n)) return in.error("expected a node block header");
    const std::size_t extra = bh[2] != 0 ? std::size_t(std::clamp(bh[0], 0L, 3L)) : 0;  // parametric u, v, w
    if (auto ok = checkCount(in, n, f.binary ? f.size + 8 * (3 + extra) : 8, "node block"); !ok) return ok;
    std::vector<long> tags(static_cast<std::size_t>(n));
    for (auto& tag : tags) {
      if (f.binary) {
        std::uint64_t t = 0;
        if (!readSize(in, f, t)) return truncated(in, "$Nodes");
        tag = long(t);
        continue;
      }
      const auto t = in.next();
      if (t.size() != 1 || !toInt(t[0], tag)) return in.error("expected a node tag");
    }
    for (long tag : tags) {
      if (f.binary) {
        std::array<double, 3> p{};
        double skip = 0;
        if (!in.read(p[0]) || !in.read(p[1]) || !in.read(p[2])) return truncated(in, "$Nodes");
        for (std::size_t k = 0; k < extra; ++k)
          if (!in.read(skip)) return truncated(in, "$Nodes");
        if (auto ok = b.addNode(in, tag, p); !ok) return ok;
        continue;
      }
      const auto t = in.next();
      if (t.size() < 3) return in.error("expected node coordinates x y z");
      if (auto ok = b.addNode(in, tag, t[0], t[1], t[2]); !ok) return ok;
    }
  }
  return {};
}

/// v4.1 $Elements: blocks of "dim tag type n", then n lines "elementTag nodeTags...".
Result<void> readElementsV4(Lines& in, Builder& b, const Format& f) {
  std::array<std::uint64_t, 4> head{};
  std::vector<long> v;
  if (!readHeader4(in, f, head)) return in.error("expected the $Elements header of v4.1");
  if (auto ok = checkCount(in, head[1], f.binary ? 2 * f.size : 4, "$Elements"); !ok) return ok;
  if (auto ok = checkCount(in, head[0], f.binary ? 12 + f.size : 8, "$Elements (entity blocks)"); !ok)
    return ok;
  for (std::uint64_t block = 0; block < head[0]; ++block) {
    std::array<long, 3> bh{};
    std::uint64_t n = 0;
    if (!readBlock4(in, f, bh, n)) return in.error("expected an element block header");
    const std::size_t count = nodesOfType(bh[2]);
    if (f.binary && count == 0)
      return in.error("binary element type " + std::to_string(bh[2]) + " is unknown to this reader");
    if (auto ok = checkCount(in, n, f.binary ? f.size * (1 + count) : 4, "element block"); !ok) return ok;
    for (std::uint64_t k = 0; k < n; ++k) {
      if (f.binary) {
        v.assign(1 + count, 0);
        for (auto& x : v) {
          std::uint64_t t = 0;
          if (!readSize(in, f, t)) return truncated(in, "$Elements");
          x = long(t);
        }
      } else if (!ints(in.next(), 0, v) || v.empty()) {
        return in.error("expected an element line of integers");
      }
      if (auto ok = b.addElement(in, bh[2], std::vector<long>(v.begin() + 1, v.end())); !ok) return ok;
    }
  }
  return {};
}

/// Reads $MeshFormat: version "2", "2.x" or "4.1", file type 0 (ASCII) or 1 (binary, followed by
/// the int 1 that tells the byte order), data size.
Result<Format> readFormat(Lines& in) {
  const auto t = in.next();
  if (t.size() < 3) return in.error("expected '$MeshFormat' version, file type and data size");
  Format f;
  if (t[0] == "2" || t[0].substr(0, 2) == "2.")
    f.major = 2;
  else if (t[0] == "4.1")
    f.major = 4;
  else
    return in.error("Gmsh format version " + std::string(t[0]) +
                    " is not supported; save as version 2 or 4.1 (ASCII or binary)");
  long type = 0, size = 0;
  if (!toInt(t[1], type) || (type != 0 && type != 1))
    return in.error("file type '" + std::string(t[1]) + "' is neither 0 (ASCII) nor 1 (binary)");
  if (!toInt(t[2], size) || (size != 4 && size != 8))
    return in.error("data size '" + std::string(t[2]) + "' is neither 4 nor 8");
  f.binary = type == 1;
  f.size = std::size_t(size);
  if (f.major == 2 && f.binary && size != 8)
    return in.error("binary version 2 needs data size 8 (doubles); this file says " + std::to_string(size));
  if (f.binary) {
    std::int32_t one = 0;
    if (!in.read(one)) return in.error("binary $MeshFormat ends before its byte-order check int");
    if (one == 0x01000000)
      in.setSwap(true);
    else if (one != 1)
      return in.error("binary $MeshFormat's check int is " + std::to_string(one) +
                      ", not 1 in either byte order; the file is damaged");
  }
  return f;
}

}  // namespace

Result<RawVolume> readGmsh(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return Error{path.string() + ": cannot open the file; check the path"};
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  Lines in(path.string(), std::move(text));
  Builder b;
  Format format;
  bool sawNodes = false;
  // Sections in any order; unknown ones ($Entities, $PhysicalNames, ...) are skipped to their end.
  for (auto t = in.next(); !t.empty(); t = in.next()) {
    Result<void> ok;
    if (t[0] == "$MeshFormat") {
      auto f = readFormat(in);
      if (!f) return f.error();
      format = *f;
    } else if (t[0] == "$NOD" || t[0] == "$Nodes") {
      ok = format.major == 4 ? readNodesV4(in, b, format)
                             : readNodesV12(in, b, t[0] == "$NOD" ? "$NOD" : "$Nodes", format);
      sawNodes = true;
    } else if (t[0] == "$ELM" || t[0] == "$Elements") {
      if (!sawNodes) return in.error("the elements come before the nodes; a .msh lists nodes first");
      ok = format.major == 4 ? readElementsV4(in, b, format) : readElementsV12(in, b, t[0] == "$ELM", format);
    } else if (t[0].size() > 1 && t[0][0] == '$' && t[0].substr(0, 4) != "$End" &&
               t[0].substr(0, 4) != "$END") {
      // Binary sections must be skipped whole; text ones may be read line by line if unterminated.
      if (!in.skipPast("$End" + std::string(t[0].substr(1))) && format.binary)
        return in.error("section " + std::string(t[0]) + " has no $End" + std::string(t[0].substr(1)) +
                        "; the file is truncated");
    }
    if (!ok) return ok.error();
  }
  if (!sawNodes) return Error{path.string() + ": no $Nodes (or $NOD) section; is this a Gmsh mesh?"};
  return std::move(b.raw);
}

}  // namespace tissue::volume::detail
