// Geometry of tet meshes: signed volumes, total volume, the boundary surface, enclosed volume.
#include <algorithm>
#include <array>

#include "tissue/volume/tet_mesh.h"

namespace tissue::volume {
namespace {

/// det(u, v, w) = u . (v x w) in double.
double det3(const Float3& af, const Float3& b, const Float3& c, const Float3& d) {
  const double ax = af.x, ay = af.y, az = af.z;
  const double ux = double{b.x} - ax, uy = double{b.y} - ay, uz = double{b.z} - az;
  const double vx = double{c.x} - ax, vy = double{c.y} - ay, vz = double{c.z} - az;
  const double wx = double{d.x} - ax, wy = double{d.y} - ay, wz = double{d.z} - az;
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

}  // namespace

double signedTetVolume(std::span<const Float3> positions, const Tet& t) {
  return det3(positions[t[0]], positions[t[1]], positions[t[2]], positions[t[3]]) / 6.0;
}

double totalVolume(const TetMesh& mesh) {
  double sum = 0.0;
  for (const Tet& t : mesh.tets)
    sum += signedTetVolume(mesh.positions, t);
  return sum;
}

std::vector<Triangle> boundaryTriangles(const TetMesh& mesh) {
  // The four faces of a positively oriented tet (v0..v3), each counter-clockwise from outside.
  static constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  struct Face {
    std::array<std::uint32_t, 3> key;  ///< sorted vertices: equal for both sides of a face
    Triangle oriented;
  };
  std::vector<Face> faces;
  faces.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets)
    for (const auto& f : kFaces) {
      Triangle tri{t[static_cast<std::size_t>(f[0])], t[static_cast<std::size_t>(f[1])],
                   t[static_cast<std::size_t>(f[2])]};
      std::array<std::uint32_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      faces.push_back({key, tri});
    }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  // A face shared by two tets is interior; one seen once is on the boundary.
  std::vector<Triangle> boundary;
  for (std::size_t k = 0; k < faces.size();) {
    std::size_t end = k + 1;
    while (end < faces.size() && faces[end].key == faces[k].key)
      ++end;
    if (end - k == 1) boundary.push_back(faces[k].oriented);
    k = end;
  }
  return boundary;
}

double enclosedVolume(std::span<const Float3> positions, std::span<const Triangle> triangles) {
  // Divergence theorem with the field x/3: V = sum over faces of a . (b x c) / 6 (origin apex).
  const Float3 origin{};
  double sum = 0.0;
  for (const Triangle& t : triangles)
    sum += det3(origin, positions[t[0]], positions[t[1]], positions[t[2]]);
  return sum / 6.0;
}

}  // namespace tissue::volume
