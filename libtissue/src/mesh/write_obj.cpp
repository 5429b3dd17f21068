#include <cstdio>
#include <string>

#include "tissue/core/atomic_file.h"
#include "tissue/mesh/load_mesh.h"

namespace tissue::mesh {

Result<void> writeObj(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  // Positions are written per geometric vertex so seams stay welded in the file.
  std::vector<Float3> geo(mesh.geometricVertexCount);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    geo[mesh.geometricIndex[i]] = mesh.positions[i];
  std::string text = "# written by tissue (units: mm)\n";
  char line[128];
  for (const auto& p : geo) {
    std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", double(p.x), double(p.y), double(p.z));
    text += line;
  }
  const bool uvs = mesh.hasUvs();
  for (std::size_t i = 0; uvs && i < mesh.uvs.size(); ++i) {
    std::snprintf(line, sizeof line, "vt %.7g %.7g\n", double(mesh.uvs[i].x), double(mesh.uvs[i].y));
    text += line;
  }
  for (const auto& t : mesh.triangles) {
    if (uvs) {
      std::snprintf(line, sizeof line, "f %u/%u %u/%u %u/%u\n", mesh.geometricIndex[t[0]] + 1, t[0] + 1,
                    mesh.geometricIndex[t[1]] + 1, t[1] + 1, mesh.geometricIndex[t[2]] + 1, t[2] + 1);
    } else {
      std::snprintf(line, sizeof line, "f %u %u %u\n", mesh.geometricIndex[t[0]] + 1,
                    mesh.geometricIndex[t[1]] + 1, mesh.geometricIndex[t[2]] + 1);
    }
    text += line;
  }
  return writeTextFileAtomic(path, text);
}

}  // namespace tissue::mesh
