#include "test_systems.h"

#include <cmath>

#include "tissue/sim/forces.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/units.h"

namespace tissue::sim::test {

MassSpringSystem oneSpring(double mass, double stiffness, double restLength) {
  SpringNetwork springs;
  addSpring(springs, 0, 1, restLength, stiffness, 0.0);
  (void)finalizeSpringNetwork(springs, 2);
  const std::uint32_t pinned[] = {0};
  return makeSystem(std::move(springs), {mass, mass}, pinned, {.gravity = {}}).value();
}

double omega(double mass, double stiffness) {
  return std::sqrt(stiffnessFromNewtonPerMm(stiffness) / mass);
}

Patch gridPatch(int nx, int ny, float spacing) {
  Patch p;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      p.positions.push_back({spacing * static_cast<float>(x), spacing * static_cast<float>(y), 0.0f});
  auto id = [nx](int x, int y) { return static_cast<std::uint32_t>(y * nx + x); };
  for (int y = 0; y + 1 < ny; ++y)
    for (int x = 0; x + 1 < nx; ++x) {
      p.triangles.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      p.triangles.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return p;
}

MassSpringSystem patchSystem(const Patch& patch, double stiffness, double damping, double totalMass,
                             const std::vector<std::uint32_t>& pinned, const SystemConfig& config) {
  SpringConfig springConfig{.stiffness = stiffness, .bendingStiffness = 0.2 * stiffness, .damping = damping};
  auto springs = buildSurfaceSprings(patch.positions, patch.triangles, springConfig).value();
  auto masses = computeMasses(patch.positions, patch.triangles, {.total = totalMass}).value();
  return makeSystem(std::move(springs), std::move(masses), pinned, config).value();
}

std::vector<Vec3d> pseudoRandomVelocities(std::size_t n, double scale) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2.0 - 1.0;
  };
  std::vector<Vec3d> v(n);
  for (Vec3d& a : v) {
    a.x = scale * next();
    a.y = scale * next();
    a.z = scale * next();
  }
  return v;
}

double largestOmega(const MassSpringSystem& system, const std::vector<Vec3d>& x) {
  const std::size_t n = x.size();
  std::vector<Vec3d> u = pseudoRandomVelocities(n, 1.0), w(n), ku(n);
  ForceScratch scratch;
  double lambda = 0.0;
  for (int it = 0; it < 2000; ++it) {
    // w = M^-1/2 K M^-1/2 u on the free vertices.
    for (std::size_t k = 0; k < n; ++k)
      w[k] = std::sqrt(system.invMasses[k]) * u[k];
    springMatrixTimes(system, x, w, 1.0, 0.0, ku, scratch);
    double norm = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      w[k] = std::sqrt(system.invMasses[k]) * ku[k];
      norm += dot(w[k], w[k]);
    }
    norm = std::sqrt(norm);
    lambda = norm;  // u has unit norm after the first iteration
    for (std::size_t k = 0; k < n; ++k)
      u[k] = (1.0 / norm) * w[k];
  }
  return std::sqrt(lambda);
}

}  // namespace tissue::sim::test
