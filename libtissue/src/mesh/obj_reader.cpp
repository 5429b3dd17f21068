// The strict OBJ reader. OpenMesh's OBJ reader is lenient in ways that hide defects: it
// silently merges repeated indices in a face, silently drops faces with fewer than three
// vertices, skips unparsable numbers and reports no line numbers (docs/DECISIONS.md). A
// surgical scene must say exactly which line of which file is wrong, so OBJ is read here;
// PLY, OFF and STL still go through OpenMesh's readers.
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>

#include "openmesh_importer.h"

namespace tissue::mesh::detail {
namespace {

std::string_view nextToken(std::string_view& line) {
  const auto start = line.find_first_not_of(" \t\r");
  if (start == std::string_view::npos) {
    line = {};
    return {};
  }
  line.remove_prefix(start);
  const auto end = line.find_first_of(" \t\r");
  const auto token = line.substr(0, end);
  line.remove_prefix(end == std::string_view::npos ? line.size() : end);
  return token;
}

/// Parses a float, accepting nan/inf spellings so they can be reported as non-finite.
bool parseFloat(std::string_view token, float& value) {
  if (token.empty()) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

bool parseInt(std::string_view token, long& value) {
  if (token.empty()) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && ptr == token.data() + token.size();
}

/// Resolves an OBJ index (1-based, or negative = relative to the end) to 0-based; -1 if bad.
long resolveIndex(long index, std::size_t count) {
  if (index > 0) return index - 1;
  if (index < 0) return long(count) + index;
  return -1;
}

}  // namespace

Result<RawMesh> readObj(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return Error{"cannot open mesh '" + path.string() + "'; check the path and permissions"};
  const std::string source = path.string();
  RawMesh raw;
  std::vector<std::array<float, 2>> uvs;
  std::string text;
  int lineNo = 0;
  const auto where = [&] { return source + ":" + std::to_string(lineNo) + ": "; };
  while (std::getline(in, text)) {
    ++lineNo;
    std::string_view line(text);
    const auto keyword = nextToken(line);
    if (keyword == "v" || keyword == "vt") {
      const int n = keyword == "v" ? 3 : 2;
      float c[3] = {0, 0, 0};
      for (int k = 0; k < n; ++k) {
        const auto token = nextToken(line);
        if (!parseFloat(token, c[k])) {
          return Error{where() + "'" + std::string(keyword) + "' needs " + std::to_string(n) +
                       " numbers but has '" + std::string(token) + "'; fix the line"};
        }
      }
      if (keyword == "v")
        raw.points.push_back({c[0], c[1], c[2]});
      else
        uvs.push_back({c[0], c[1]});
    } else if (keyword == "f") {
      std::vector<int> polygon;
      std::vector<std::array<float, 2>> corners;
      bool cornerMissing = false;
      for (auto token = nextToken(line); !token.empty(); token = nextToken(line)) {
        const auto slash = token.find('/');
        long v = 0, t = 0;
        if (!parseInt(token.substr(0, slash), v) || resolveIndex(v, raw.points.size()) < 0 ||
            std::size_t(resolveIndex(v, raw.points.size())) >= raw.points.size()) {
          return Error{where() + "face vertex '" + std::string(token) + "' refers to no vertex (" +
                       std::to_string(raw.points.size()) + " defined so far); fix the index"};
        }
        polygon.push_back(int(resolveIndex(v, raw.points.size())));
        const auto uvPart = slash == std::string_view::npos ? std::string_view{} : token.substr(slash + 1);
        const auto uvText = uvPart.substr(0, uvPart.find('/'));
        if (uvText.empty()) {
          cornerMissing = true;
          continue;
        }
        const long ti = parseInt(uvText, t) ? resolveIndex(t, uvs.size()) : -1;
        if (ti < 0 || std::size_t(ti) >= uvs.size()) {
          return Error{where() + "face vertex '" + std::string(token) +
                       "' refers to no texture coordinate (" + std::to_string(uvs.size()) +
                       " defined so far); fix the index"};
        }
        corners.push_back(uvs[std::size_t(ti)]);
      }
      raw.polygons.push_back(std::move(polygon));
      raw.cornerUvs.push_back(cornerMissing ? std::vector<std::array<float, 2>>{} : std::move(corners));
      raw.polygonLines.push_back(lineNo);
    }
    // Other statements (vn, o, g, s, usemtl, mtllib, l, comments) carry nothing the mesh needs.
  }
  return raw;
}

}  // namespace tissue::mesh::detail
