#pragma once
// A small organ for the scene module's tests: a flat 2 mm grid with UVs, pinned at its border,
// poked by a sphere coming down onto its centre (surface springs; milliseconds per frame).
#include <filesystem>
#include <fstream>
#include <string>

#include "tissue/scenario/scenario.h"

namespace tissue::test {

/// Writes the grid OBJ (n x n vertices, `spacing` mm, z = 0, with UVs) and a scenario poking it
/// into `dir`; returns the scenario's path.
inline std::filesystem::path writePokedGrid(const std::filesystem::path& dir, int n = 15,
                                            double spacing = 2.0, int frames = 60) {
  std::filesystem::create_directories(dir);
  std::ofstream obj(dir / "grid.obj");
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      obj << "v " << x * spacing << ' ' << y * spacing << " 0\nvt " << double(x) / (n - 1) << ' '
          << double(y) / (n - 1) << '\n';
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x + 1, b = a + 1, c = a + n + 1, d = a + n;
      obj << "f " << a << '/' << a << ' ' << b << '/' << b << ' ' << c << '/' << c << "\nf " << a << '/' << a
          << ' ' << c << '/' << c << ' ' << d << '/' << d << '\n';
    }
  std::string pins;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (x == 0 || y == 0 || x == n - 1 || y == n - 1)
        pins += (pins.empty() ? "" : ", ") + std::to_string(y * n + x);
  const double c = (n - 1) * spacing / 2.0;
  std::ofstream json(dir / "grid_poke.json");
  json << R"({"mesh": "grid.obj",
    "springs": {"from": "surface", "stiffness": 0.05, "bending_stiffness": 0.005},
    "mass": {"density": 0.001}, "gravity": [0, 0, 0], "damping": {"springs": 0.0005, "rayleigh_mass": 5},
    "pinned": [)"
       << pins << R"(], "frames": )" << frames << R"(,
    "instrument": {"shape": "sphere", "radius": 3, "path": [
      {"time": 0, "position": [)"
       << c << ", " << c << R"(, 6]}, {"time": 0.5, "position": [)" << c << ", " << c << R"(, 1]}]}})";
  return dir / "grid_poke.json";
}

}  // namespace tissue::test
