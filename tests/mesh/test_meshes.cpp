#include "test_meshes.h"

#include <cmath>
#include <fstream>
#include <numbers>

namespace tissue::test {

SurfaceMesh makeGrid(int nx, int ny, float sx, float sy) {
  SurfaceMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const float u = float(i) / float(nx), v = float(j) / float(ny);
      m.positions.push_back({u * sx, v * sy, 0.0f});
      m.uvs.push_back({u, v});
      m.geometricIndex.push_back(std::uint32_t(m.geometricIndex.size()));
    }
  m.geometricVertexCount = std::uint32_t(m.positions.size());
  const auto id = [nx](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

SurfaceMesh makeUvSphere(float radius, int stacks, int slices) {
  SurfaceMesh m;
  // Geometric vertices: north pole, (stacks - 1) rings of `slices`, south pole.
  const auto geoId = [&](int s, int k) -> std::uint32_t {
    if (s == 0) return 0;
    if (s == stacks) return std::uint32_t(1 + (stacks - 1) * slices);
    return std::uint32_t(1 + (s - 1) * slices + (k % slices));
  };
  m.geometricVertexCount = std::uint32_t(2 + (stacks - 1) * slices);
  // Render vertices: (stacks + 1) x (slices + 1), the column k = slices duplicating k = 0 (seam).
  for (int s = 0; s <= stacks; ++s)
    for (int k = 0; k <= slices; ++k) {
      const double theta = std::numbers::pi * s / stacks, phi = 2.0 * std::numbers::pi * k / slices;
      const int kk = (s == 0 || s == stacks) ? 0 : k % slices;
      const double ph = 2.0 * std::numbers::pi * kk / slices;
      const double rr = double(radius);
      m.positions.push_back({float(rr * std::sin(theta) * std::cos(ph)),
                             float(rr * std::sin(theta) * std::sin(ph)), float(rr * std::cos(theta))});
      m.uvs.push_back({float(phi / (2.0 * std::numbers::pi)), float(1.0 - double(s) / stacks)});
      m.geometricIndex.push_back(geoId(s, k));
    }
  const auto id = [slices](int s, int k) { return std::uint32_t(s * (slices + 1) + k); };
  for (int s = 0; s < stacks; ++s)
    for (int k = 0; k < slices; ++k) {
      // Outward (counter-clockwise seen from outside): theta grows downwards, phi eastwards.
      if (s != 0) m.triangles.push_back({id(s, k), id(s + 1, k), id(s, k + 1)});
      if (s != stacks - 1) m.triangles.push_back({id(s, k + 1), id(s + 1, k), id(s + 1, k + 1)});
    }
  return m;
}

std::filesystem::path writeTestFile(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "mesh";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

double angleBetween(Float3 a, Float3 b) {
  const double cx = double(a.y) * double(b.z) - double(a.z) * double(b.y);
  const double cy = double(a.z) * double(b.x) - double(a.x) * double(b.z);
  const double cz = double(a.x) * double(b.y) - double(a.y) * double(b.x);
  const double d = double(a.x) * double(b.x) + double(a.y) * double(b.y) + double(a.z) * double(b.z);
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), d);
}

}  // namespace tissue::test
