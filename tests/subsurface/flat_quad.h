#pragma once
// A 100 x 100 mm flat quad in z = 0 with unit UVs, its exact normals, tangents and planes
// (eq. 14: the fitted plane of a flat surface is the surface), as the CPU ray-march model sees
// it. Shared by the subsurface and the studies tests.
#include <vector>

#include "tissue/subsurface/reference_image.h"

namespace tissue::test {

struct FlatQuad {
  std::vector<Float3> positions = {{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}};
  std::vector<Float3> normals = std::vector<Float3>(4, Float3{0, 0, 1});
  std::vector<Float4> tangents = std::vector<Float4>(4, Float4{1, 0, 0, 1});
  std::vector<Float4> planes = std::vector<Float4>(4, Float4{0, 0, 1, 0});
  std::vector<Float2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}};
  subsurface::MeshView view() const {
    return {positions,
            normals,
            tangents,
            planes,
            uvs,
            triangles,
            subsurface::uvPerMmOf(positions, uvs, triangles)};
  }
};

}  // namespace tissue::test
