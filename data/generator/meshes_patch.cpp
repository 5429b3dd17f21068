#include <cmath>

#include "meshes.h"
#include "noise.h"
#include "rng.h"
#include "uv_layout.h"

namespace tissue::datagen {
namespace {

/// A Gaussian bump of the patch's height field.
struct Bump {
  double x = 0.0, y = 0.0;  ///< centre, mm
  double height = 0.0;      ///< mm
  double sigma = 1.0;       ///< mm
};

/// Height (mm) of the patch at (x, y) mm: a shallow dome (radius of curvature 250 mm), soft
/// Gaussian bumps and a faint low-frequency ripple.
double patchHeight(double x, double y, const std::vector<Bump>& bumps) {
  double z = 5.0 - (x * x + y * y) / (2.0 * 250.0);
  for (const Bump& b : bumps) {
    const double r2 = (x - b.x) * (x - b.x) + (y - b.y) * (y - b.y);
    z += b.height * std::exp(-r2 / (2.0 * b.sigma * b.sigma));
  }
  return z + 0.4 * fbm(x / 20.0, y / 20.0, 0.5, 3, 0x9a7c4u);
}

}  // namespace

UvMesh makePatch() {
  // Step 1: the bumps, from a fixed seed.
  Rng rng(0x7a7c4001u);
  std::vector<Bump> bumps(7);
  for (Bump& b : bumps) {
    b.x = rng.uniform(-32.0, 32.0);
    b.y = rng.uniform(-22.0, 22.0);
    b.height = rng.uniform(0.8, 2.5) * (rng.uniform() < 0.25 ? -1.0 : 1.0);
    b.sigma = rng.uniform(5.0, 12.0);
  }
  // Step 2: the grid of vertices; one UV per vertex (a single planar chart, no seams).
  UvMesh mesh;
  for (int j = 0; j < kPatchGridY; ++j) {
    for (int i = 0; i < kPatchGridX; ++i) {
      const double x = kPatchWidthMm * (double(i) / (kPatchGridX - 1) - 0.5);
      const double y = kPatchHeightMm * (double(j) / (kPatchGridY - 1) - 0.5);
      mesh.positions.push_back({float(x), float(y), float(patchHeight(x, y, bumps))});
      mesh.uvs.push_back(patchUv(x, y));
    }
  }
  // Step 3: two triangles per cell, counter-clockwise seen from +z (the outside).
  for (int j = 0; j + 1 < kPatchGridY; ++j) {
    for (int i = 0; i + 1 < kPatchGridX; ++i) {
      const auto v00 = std::uint32_t(j * kPatchGridX + i), v10 = v00 + 1;
      const auto v01 = v00 + std::uint32_t(kPatchGridX), v11 = v01 + 1;
      mesh.triangles.push_back({v00, v10, v11});
      mesh.triangles.push_back({v00, v11, v01});
    }
  }
  mesh.uvTriangles = mesh.triangles;
  return mesh;
}

}  // namespace tissue::datagen
