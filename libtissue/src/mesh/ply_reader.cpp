// The PLY reader (ASCII, binary little- and big-endian). Hand-written because OpenMesh 9's PLY
// reader misreads files MeshLab and VTK open (docs/DECISIONS.md): it ignores `element tristrips`
// (a strip-only file has "no faces"), and a list property it does not know on a vertex or face
// shifts every later number of the element. Here every element and property of the header is
// read by its declared type, unknown ones are skipped by that type, and each count is checked
// against the bytes left before anything is allocated for it.
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "openmesh_importer.h"

namespace tissue::mesh::detail {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Invalid };

PlyType plyType(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return PlyType::Invalid;
}

std::size_t sizeOf(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    default:
      return 8;
  }
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Invalid;
  bool list = false;
  PlyType countType = PlyType::Invalid;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int headerLine = 0;
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

/// Reads the numbers of the body, text or binary; errors name the file and the place.
class PlyBody {
 public:
  PlyBody(std::string_view data, PlyFormat format, int firstLine)
      : m_data(data), m_format(format), m_line(firstLine) {}

  int line() const { return m_line; }
  bool ascii() const { return m_format == PlyFormat::Ascii; }
  std::size_t remaining() const { return m_data.size() - m_pos; }

  /// The least number of bytes `n` values of `type` take (text: a digit and a separator each).
  std::uint64_t minBytes(std::uint64_t n, PlyType type) const { return n * (ascii() ? 2 : sizeOf(type)); }

  bool read(PlyType type, double& value) { return ascii() ? readText(value) : readBinary(type, value); }

  /// Text: the line the next number is on.
  int nextLine() {
    while (m_pos < m_data.size() && std::isspace(static_cast<unsigned char>(m_data[m_pos]))) {
      if (m_data[m_pos] == '\n') ++m_line;
      ++m_pos;
    }
    return m_line;
  }

 private:
  bool readText(double& value) {
    nextLine();
    const std::size_t start = m_pos;
    while (m_pos < m_data.size() && !std::isspace(static_cast<unsigned char>(m_data[m_pos])))
      ++m_pos;
    if (m_pos == start) return false;
    const auto [end, ec] = std::from_chars(m_data.data() + start, m_data.data() + m_pos, value);
    return ec == std::errc() && end == m_data.data() + m_pos;
  }
  bool readBinary(PlyType type, double& value) {
    const std::size_t n = sizeOf(type);
    if (remaining() < n) return false;
    unsigned char bytes[8];
    std::memcpy(bytes, m_data.data() + m_pos, n);
    m_pos += n;
    const bool fileLittle = m_format == PlyFormat::LittleEndian;
    if (fileLittle != (std::endian::native == std::endian::little))
      for (std::size_t k = 0; k < n / 2; ++k)
        std::swap(bytes[k], bytes[n - 1 - k]);
    switch (type) {
      case PlyType::Int8:
        value = double(std::int8_t(bytes[0]));
        break;
      case PlyType::UInt8:
        value = double(bytes[0]);
        break;
      case PlyType::Int16:
        value = double(load<std::int16_t>(bytes));
        break;
      case PlyType::UInt16:
        value = double(load<std::uint16_t>(bytes));
        break;
      case PlyType::Int32:
        value = double(load<std::int32_t>(bytes));
        break;
      case PlyType::UInt32:
        value = double(load<std::uint32_t>(bytes));
        break;
      case PlyType::Float32:
        value = double(load<float>(bytes));
        break;
      default:
        value = load<double>(bytes);
        break;
    }
    return true;
  }
  template <class T>
  static T load(const unsigned char* bytes) {
    T v;
    std::memcpy(&v, bytes, sizeof(T));
    return v;
  }

  std::string_view m_data;
  PlyFormat m_format;
  std::size_t m_pos = 0;
  int m_line;
};

/// Header parse result.
struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;
  int bodyLine = 1;
};

Result<PlyHeader> readHeader(const std::string& text, const std::string& file) {
  PlyHeader h;
  std::size_t pos = 0;
  int lineNo = 0;
  bool sawFormat = false;
  while (true) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos)
      return Error{file + ": the PLY header has no 'end_header' line; the file is truncated or not a PLY"};
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream in(line);
    std::string word;
    in >> word;
    const std::string where = file + ":" + std::to_string(lineNo) + ": ";
    if (lineNo == 1) {
      if (word != "ply") return Error{where + "a PLY file starts with 'ply'; this is not a PLY file"};
      continue;
    }
    if (word.empty() || word == "comment" || word == "obj_info") continue;
    if (word == "end_header") break;
    if (word == "format") {
      std::string kind;
      in >> kind;
      if (kind == "ascii")
        h.format = PlyFormat::Ascii;
      else if (kind == "binary_little_endian")
        h.format = PlyFormat::LittleEndian;
      else if (kind == "binary_big_endian")
        h.format = PlyFormat::BigEndian;
      else
        return Error{where + "unknown PLY format '" + kind +
                     "'; use ascii, binary_little_endian or binary_big_endian"};
      sawFormat = true;
    } else if (word == "element") {
      PlyElement e;
      e.headerLine = lineNo;
      std::string count;
      if (!(in >> e.name >> count)) return Error{where + "expected 'element NAME COUNT'"};
      // Digits only: an unsigned read would wrap "-4" to 2^64 - 4 (found by the PLY fuzz target:
      // an element of no properties and such a count looped without end).
      if (count.empty() || count.size() > 19 || count.find_first_not_of("0123456789") != std::string::npos)
        return Error{where + "element '" + e.name + "' has the count '" + count +
                     "'; give a non-negative whole number"};
      e.count = std::stoull(count);
      h.elements.push_back(std::move(e));
    } else if (word == "property") {
      if (h.elements.empty())
        return Error{where + "a property before any element; declare the element first"};
      PlyProperty p;
      std::string type;
      in >> type;
      if (type == "list") {
        std::string countType, valueType;
        in >> countType >> valueType;
        p.list = true;
        p.countType = plyType(countType);
        p.type = plyType(valueType);
        if (p.countType == PlyType::Invalid || p.countType == PlyType::Float32 ||
            p.countType == PlyType::Float64)
          return Error{where + "list count type '" + countType + "' is not an integer type"};
      } else {
        p.type = plyType(type);
      }
      if (p.type == PlyType::Invalid || !(in >> p.name))
        return Error{where +
                     "expected 'property TYPE NAME' with a PLY type (char, uchar, short, ushort, int, "
                     "uint, float, double)"};
      h.elements.back().properties.push_back(std::move(p));
    } else {
      return Error{where + "unknown PLY header keyword '" + word + "'"};
    }
  }
  if (!sawFormat) return Error{file + ": the PLY header has no 'format' line"};
  h.bodyOffset = pos;
  h.bodyLine = lineNo + 1;
  return h;
}

int indexOf(const PlyElement& e, std::initializer_list<std::string_view> names) {
  for (std::size_t k = 0; k < e.properties.size(); ++k)
    for (auto n : names)
      if (e.properties[k].name == n) return int(k);
  return -1;
}

}  // namespace

Result<RawMesh> readPly(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream stream(path, std::ios::binary);
  if (!stream) return Error{"cannot open mesh '" + file + "'; check the path and permissions"};
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  auto header = readHeader(text, file);
  if (!header) return header.error();
  PlyBody body(std::string_view(text).substr(header->bodyOffset), header->format, header->bodyLine);
  RawMesh raw;
  std::vector<double> list;
  for (const auto& e : header->elements) {
    // Bounded memory: the declared count must fit in the bytes left.
    std::uint64_t perItem = 0;
    for (const auto& p : e.properties)
      perItem += p.list ? body.minBytes(1, p.countType) : body.minBytes(1, p.type);
    if (e.properties.empty()) {
      if (!body.ascii()) continue;  // binary items of no properties take no bytes: nothing to read
      perItem = 1;                  // an ASCII item is at least its line's end
    }
    if (perItem > 0 && e.count > (body.remaining() + 1) / perItem)
      return Error{file + ":" + std::to_string(e.headerLine) + ": element '" + e.name + "' declares " +
                   std::to_string(e.count) + " entries, more than the " + std::to_string(body.remaining()) +
                   " bytes left can hold; fix the count or the truncated file"};
    const bool isVertex = e.name == "vertex";
    const bool isFace = e.name == "face";
    const bool isStrip = e.name == "tristrips";
    const int x = indexOf(e, {"x"}), y = indexOf(e, {"y"}), z = indexOf(e, {"z"});
    const int u = indexOf(e, {"u", "s", "texture_u", "texture_s"});
    const int v = indexOf(e, {"v", "t", "texture_v", "texture_t"});
    const int indices = indexOf(e, {"vertex_indices", "vertex_index"});
    const int texcoord = indexOf(e, {"texcoord"});
    if (isVertex && (x < 0 || y < 0 || z < 0))
      return Error{file + ":" + std::to_string(e.headerLine) +
                   ": element vertex has no x, y and z properties"};
    if ((isFace || isStrip) && (indices < 0 || !e.properties[std::size_t(indices)].list))
      return Error{file + ":" + std::to_string(e.headerLine) + ": element " + e.name +
                   " has no 'vertex_indices' list property"};
    const bool vertexUvs = isVertex && u >= 0 && v >= 0;
    if (isVertex) {
      raw.points.reserve(std::size_t(e.count));
      if (vertexUvs) raw.vertexUvs.reserve(std::size_t(e.count));
    }
    for (std::uint64_t item = 0; item < e.count; ++item) {
      const int itemLine = body.ascii() ? body.nextLine() : 0;
      const auto fail = [&](const std::string& what) {
        const std::string where = body.ascii() ? file + ":" + std::to_string(body.line())
                                               : file + ": " + e.name + " " + std::to_string(item + 1);
        return Error{where + ": " + what};
      };
      std::array<double, 3> p{};
      std::array<double, 2> uv{};
      std::vector<int> polygon;
      std::vector<std::array<float, 2>> corners;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const auto& prop = e.properties[k];
        double value = 0;
        if (!prop.list) {
          if (!body.read(prop.type, value))
            return fail("expected a number for property '" + prop.name + "' of " + e.name + " " +
                        std::to_string(item + 1) + "; the file is truncated or malformed");
          const int ik = int(k);
          if (ik == x) p[0] = value;
          if (ik == y) p[1] = value;
          if (ik == z) p[2] = value;
          if (ik == u) uv[0] = value;
          if (ik == v) uv[1] = value;
          continue;
        }
        double count = 0;
        if (!body.read(prop.countType, count) || count < 0 || count != std::floor(count))
          return fail("expected a list length for property '" + prop.name + "'");
        // Compared as a double first: a text length such as 1e126 does not fit the integer
        // (found by the PLY fuzzer: UBSan, float-cast-overflow).
        if (count > double(body.remaining()) ||
            body.minBytes(std::uint64_t(count), prop.type) > body.remaining() + 1) {
          std::ostringstream declared;
          declared << std::setprecision(15) << count;
          return fail("list '" + prop.name + "' declares " + declared.str() +
                      " entries, more than the file holds");
        }
        list.resize(std::size_t(count));
        for (auto& entry : list)
          if (!body.read(prop.type, entry)) return fail("expected a number in list '" + prop.name + "'");
        if (int(k) == indices) {
          for (double idx : list) {
            if (isStrip && idx == 4294967295.0) idx = -1;  // a restart written as an unsigned list
            if (idx != std::floor(idx) || std::abs(idx) > 2147483647.0)
              return fail("vertex index " + std::to_string(idx) + " is not an integer index");
            polygon.push_back(int(idx));
          }
        } else if (int(k) == texcoord && isFace) {
          for (std::size_t c = 0; c + 1 < list.size(); c += 2)
            corners.push_back({float(list[c]), float(list[c + 1])});
        }
      }
      if (isVertex) {
        raw.points.push_back({float(p[0]), float(p[1]), float(p[2])});
        if (vertexUvs) raw.vertexUvs.push_back({float(uv[0]), float(uv[1])});
      } else if (isFace) {
        if (!corners.empty() && corners.size() != polygon.size())
          return fail("face " + std::to_string(item + 1) + " has " + std::to_string(corners.size()) +
                      " texture coordinates for " + std::to_string(polygon.size()) + " corners");
        raw.polygons.push_back(std::move(polygon));
        raw.cornerUvs.push_back(std::move(corners));
        if (body.ascii()) raw.polygonLines.push_back(itemLine);
      } else if (isStrip) {
        // -1 restarts a strip (MeshLab and VTK write one list of several strips).
        std::vector<int> strip;
        for (int idx : polygon) {
          if (idx < 0) {
            appendStripTriangles(strip, body.ascii() ? itemLine : 0, raw);
            strip.clear();
          } else {
            strip.push_back(idx);
          }
        }
        appendStripTriangles(strip, body.ascii() ? itemLine : 0, raw);
      }
    }
  }
  return raw;
}

void appendStripTriangles(const std::vector<int>& strip, int line, RawMesh& out) {
  for (std::size_t i = 2; i < strip.size(); ++i) {
    std::vector<int> tri = (i % 2 == 0) ? std::vector<int>{strip[i - 2], strip[i - 1], strip[i]}
                                        : std::vector<int>{strip[i - 1], strip[i - 2], strip[i]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    out.polygons.push_back(std::move(tri));
    out.cornerUvs.emplace_back();
    if (line > 0) out.polygonLines.push_back(line);
  }
}

}  // namespace tissue::mesh::detail
