#include <cmath>

#include "meshes.h"
#include "noise.h"
#include "uv_layout.h"

namespace tissue::datagen {
namespace {

/// Liver-like surface point (mm) for a unit direction `d` (x: patient's right, y: anterior,
/// z: superior). Every step scales within planes of constant x by positive factors, so each
/// slice stays star-shaped and the displaced cube-sphere stays embedded (no fold-overs).
Eigen::Vector3d liverPoint(const Eigen::Vector3d& d) {
  const double x = d.x(), y = d.y(), z = d.z();
  // Step 1: the right lobe (+x) is thick and deep; the left lobe tapers to a thin edge.
  const double taper = smoothstep(-1.0, 0.5, x);
  const double bulge = 1.0 + 0.12 * std::exp(-((x - 0.4) / 0.3) * ((x - 0.4) / 0.3));
  const double depthScale = 0.62 + 0.38 * taper;
  const double heightScale = (0.32 + 0.68 * taper) * bulge;
  // Step 2: domed diaphragmatic surface above, flatter visceral surface below.
  const double zShaped = z * (0.8 + 0.2 * std::tanh(z / 0.3));
  // Step 3: the notch (ligamentum teres) on the anterior border, left of the middle.
  const double notch =
      1.0 - 0.22 * std::exp(-((x + 0.12) / 0.09) * ((x + 0.12) / 0.09)) * smoothstep(0.2, 0.9, y);
  return {90.0 * x, 60.0 * y * depthScale * notch, 50.0 * zShaped * heightScale * notch};
}

}  // namespace

UvMesh makeLiver() {
  constexpr int n = kLiverFaceQuads;
  constexpr int side = n + 1;
  UvMesh mesh;
  // Step 1: one position per lattice point of the cube surface, shared by the faces that meet there.
  std::vector<std::int32_t> latticeIndex(std::size_t(side) * side * side, -1);
  std::vector<std::uint32_t> faceVertex(std::size_t(6) * side * side);
  for (int face = 0; face < 6; ++face) {
    for (int b = 0; b < side; ++b) {
      for (int a = 0; a < side; ++a) {
        const Eigen::Vector3d c = cubeFacePoint(face, double(a) / n, double(b) / n);
        const Eigen::Vector3i l = ((c + Eigen::Vector3d::Ones()) * (0.5 * n)).array().round().cast<int>();
        std::int32_t& index = latticeIndex[(std::size_t(l.x()) * side + l.y()) * side + l.z()];
        if (index < 0) {
          const Eigen::Vector3d p = liverPoint(cubeToSphere(c).normalized());
          index = std::int32_t(mesh.positions.size());
          mesh.positions.push_back({float(p.x()), float(p.y()), float(p.z())});
        }
        faceVertex[(std::size_t(face) * side + b) * side + a] = std::uint32_t(index);
        mesh.uvs.push_back(liverUv(face, double(a) / n, double(b) / n));
      }
    }
  }
  // Step 2: two triangles per face cell; u x v is the outward normal, so (a, b) -> (a + 1, b) ->
  // (a + 1, b + 1) is counter-clockwise from outside. Diagonals alternate by quadrant so the
  // triangulation is symmetric about each face centre.
  for (int face = 0; face < 6; ++face) {
    for (int b = 0; b < n; ++b) {
      for (int a = 0; a < n; ++a) {
        const auto t00 = std::uint32_t((face * side + b) * side + a), t10 = t00 + 1;
        const auto t01 = t00 + std::uint32_t(side), t11 = t01 + 1;
        const bool flip = (a < n / 2) != (b < n / 2);
        const Triangle first = flip ? Triangle{t00, t10, t01} : Triangle{t00, t10, t11};
        const Triangle second = flip ? Triangle{t10, t11, t01} : Triangle{t00, t11, t01};
        for (const Triangle& t : {first, second}) {
          mesh.uvTriangles.push_back(t);
          mesh.triangles.push_back({faceVertex[t[0]], faceVertex[t[1]], faceVertex[t[2]]});
        }
      }
    }
  }
  return mesh;
}

}  // namespace tissue::datagen
