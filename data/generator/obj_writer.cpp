#include <cstdio>
#include <sstream>

#include "uv_mesh.h"

namespace tissue::datagen {

std::string toObj(const UvMesh& mesh, const std::string& header) {
  std::string out;
  out.reserve(mesh.positions.size() * 40 + mesh.uvs.size() * 24 + mesh.triangles.size() * 40);
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);)
    out += "# " + line + "\n";
  char buffer[128];
  // Fixed-point formats: identical text on every run and platform with IEEE floats.
  for (const Float3& p : mesh.positions) {
    std::snprintf(buffer, sizeof buffer, "v %.5f %.5f %.5f\n", double(p.x), double(p.y), double(p.z));
    out += buffer;
  }
  for (const Float2& t : mesh.uvs) {
    std::snprintf(buffer, sizeof buffer, "vt %.6f %.6f\n", double(t.x), double(t.y));
    out += buffer;
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& f = mesh.triangles[i];
    const Triangle& t = mesh.uvTriangles[i];
    std::snprintf(buffer, sizeof buffer, "f %u/%u %u/%u %u/%u\n", f[0] + 1, t[0] + 1, f[1] + 1, t[1] + 1,
                  f[2] + 1, t[2] + 1);
    out += buffer;
  }
  return out;
}

}  // namespace tissue::datagen
