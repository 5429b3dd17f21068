#pragma once
// A flat box mesh for the truth's tests: top face at z = 0 (outward normal +z), bottom face at
// z = -thickness, sides at x, y = +-halfWidth; triangles counter-clockwise seen from outside;
// UVs (x, y) mapped to [0, 1]^2 (u grows with x, v with y).
#include <vector>

#include "tissue/optics/monte_carlo.h"

#include "tissue/truth/path_tracer.h"

namespace tissue::test {

struct SlabBox {
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
  std::vector<Float2> uvs;
  SlabBox(float halfWidthMm, float thicknessMm) {
    const float w = halfWidthMm, z0 = 0.0f, z1 = -thicknessMm;
    positions = {{-w, -w, z1}, {w, -w, z1}, {w, w, z1}, {-w, w, z1},
                 {-w, -w, z0}, {w, -w, z0}, {w, w, z0}, {-w, w, z0}};
    triangles = {{4, 5, 6}, {4, 6, 7},   // top (+z)
                 {0, 2, 1}, {0, 3, 2},   // bottom (-z)
                 {0, 1, 5}, {0, 5, 4},   // y = -w
                 {2, 3, 7}, {2, 7, 6},   // y = +w
                 {1, 2, 6}, {1, 6, 5},   // x = +w
                 {3, 0, 4}, {3, 4, 7}};  // x = -w
    for (const Float3& p : positions)
      uvs.push_back({(p.x + w) / (2.0f * w), (p.y + w) / (2.0f * w)});
  }
  truth::TruthMesh mesh() const { return {positions, triangles, uvs}; }
};

/// The 1D Monte Carlo (MCML's model) of one band of a constant-depth material: 1e5 photons on
/// 2 threads; an Error when the material has no slab form.
inline Result<optics::MonteCarloResult> slabMonteCarlo(const truth::TruthMaterial& material, int band,
                                                       std::uint64_t seed) {
  auto medium = truth::toLayeredMedium(material, band);
  if (!medium) return medium.error();
  optics::MonteCarloSettings mc;
  mc.photons = 100000;
  mc.seed = seed;
  mc.threads = 2;
  return optics::simulateMonteCarlo(*medium, mc);
}

}  // namespace tissue::test
