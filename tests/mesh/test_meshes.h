#pragma once
// Procedural meshes with known geometry for the mesh-module tests.

#include <filesystem>
#include <string>

#include "tissue/core/surface_mesh.h"

namespace tissue::test {

/// An nx x ny grid in the z = 0 plane, size sx x sy mm, uv = (x / sx, y / sy), normal +z.
SurfaceMesh makeGrid(int nx, int ny, float sx, float sy);

/// A UV sphere of radius r mm (stacks x slices) with a seam at u = 0/1 and poles; welded
/// geometric vertices, split render vertices.
SurfaceMesh makeUvSphere(float radius, int stacks, int slices);

/// Writes `text` to a fresh file under the test output folder and returns its path.
std::filesystem::path writeTestFile(const std::string& name, const std::string& text);

/// The largest angle (rad) between two unit vectors.
double angleBetween(Float3 a, Float3 b);

}  // namespace tissue::test
