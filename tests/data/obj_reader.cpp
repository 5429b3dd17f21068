#include "obj_reader.h"

#include <sstream>

#include "tissue/core/atomic_file.h"

namespace tissue::datatest {
namespace {

/// Parses "a/b" into two 1-based indices.
bool parseCorner(const std::string& token, std::uint32_t& v, std::uint32_t& vt) {
  const auto slash = token.find('/');
  if (slash == std::string::npos) return false;
  try {
    const long a = std::stol(token.substr(0, slash)), b = std::stol(token.substr(slash + 1));
    if (a < 1 || b < 1) return false;
    v = std::uint32_t(a - 1);
    vt = std::uint32_t(b - 1);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

Result<ObjMesh> parseObj(const std::string& text) {
  ObjMesh mesh;
  std::istringstream lines(text);
  int lineNumber = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    if (tag == "v") {
      Float3 p;
      if (!(in >> p.x >> p.y >> p.z)) return Error{"bad v on line " + std::to_string(lineNumber)};
      mesh.positions.push_back(p);
    } else if (tag == "vt") {
      Float2 t;
      if (!(in >> t.x >> t.y)) return Error{"bad vt on line " + std::to_string(lineNumber)};
      mesh.uvs.push_back(t);
    } else if (tag == "f") {
      Triangle f{}, t{};
      std::string corner[4];
      in >> corner[0] >> corner[1] >> corner[2] >> corner[3];
      if (!corner[3].empty()) return Error{"non-triangle face on line " + std::to_string(lineNumber)};
      for (int k = 0; k < 3; ++k) {
        if (!parseCorner(corner[k], f[k], t[k])) return Error{"bad f on line " + std::to_string(lineNumber)};
      }
      mesh.triangles.push_back(f);
      mesh.uvTriangles.push_back(t);
    }
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (mesh.triangles[i][k] >= mesh.positions.size() || mesh.uvTriangles[i][k] >= mesh.uvs.size()) {
        return Error{"face " + std::to_string(i) + " indexes past the end"};
      }
    }
  }
  return mesh;
}

Result<ObjMesh> readObj(const std::filesystem::path& path) {
  auto text = readTextFile(path);
  if (!text) return text.error();
  return parseObj(*text);
}

}  // namespace tissue::datatest
