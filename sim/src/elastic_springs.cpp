// Spring stiffness from material constants (E, nu, density), see elastic_springs.h.
#include "tissue/sim/elastic_springs.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

/// Spring index of each (unordered) vertex pair of `network`.
std::unordered_map<std::uint64_t, std::uint32_t> springIndex(const SpringNetwork& network) {
  std::unordered_map<std::uint64_t, std::uint32_t> out;
  out.reserve(network.size() * 2);
  for (std::uint32_t s = 0; s < network.size(); ++s)
    out.emplace(pairKey(network.i[s], network.j[s]), s);
  return out;
}

std::string shown(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

/// Writes `stiffnessNPerMm` (N/mm, one per spring) into the network (g/s^2).
void store(SpringNetwork& network, const std::vector<double>& stiffnessNPerMm) {
  for (std::size_t s = 0; s < network.size(); ++s)
    network.stiffness[s] = stiffnessFromNewtonPerMm(stiffnessNPerMm[s]);
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace

Result<void> validateMaterial(const ElasticMaterial& m) {
  if (!(m.youngsModulusKpa > 0.0) || !std::isfinite(m.youngsModulusKpa))
    return Error{"youngs_modulus_kpa: expected a positive number (kPa), got " + shown(m.youngsModulusKpa)};
  if (!(m.poissonRatio > 0.0 && m.poissonRatio < 0.5))
    return Error{
        "poisson_ratio: expected a number in (0, 0.5) (dimensionless; 0.5 is incompressible and "
        "not reachable), got " +
        shown(m.poissonRatio)};
  if (!(m.densityGPerMm3 > 0.0) || !std::isfinite(m.densityGPerMm3))
    return Error{"density_g_per_mm3: expected a positive number (g/mm^3, liver 1.06e-3), got " +
                 shown(m.densityGPerMm3)};
  return {};
}

Result<void> setTetEdgeStiffness(SpringNetwork& network, std::span<const Vec3d> positions,
                                 std::span<const Tet> tets, const ElasticMaterial& material,
                                 TetStiffnessFormula formula) {
  if (auto ok = validateMaterial(material); !ok) return ok;
  const double e = kpaToNewtonPerMm2(material.youngsModulusKpa);  // N/mm^2
  const auto index = springIndex(network);
  std::vector<double> k(network.size(), 0.0);
  std::vector<char> used(network.size(), 0);
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& tet = tets[t];
    for (std::uint32_t v : tet)
      if (v >= positions.size())
        return Error{"tet " + std::to_string(t) + ": vertex " + std::to_string(v) + " out of range"};
    const Vec3d p0 = positions[tet[0]];
    const double volume =
        std::abs(dot(positions[tet[1]] - p0, cross(positions[tet[2]] - p0, positions[tet[3]] - p0))) / 6.0;
    if (!(volume > 0.0)) return Error{"tet " + std::to_string(t) + ": zero volume"};
    // Lloyd et al. 2007: the regular tet of the same volume, l = (6 sqrt2 V)^(1/3), k = (2 sqrt2/25) E l.
    double perEdge = 2.0 * std::sqrt(2.0) / 25.0 * e * std::cbrt(6.0 * std::sqrt(2.0) * volume);
    if (formula == TetStiffnessFormula::LloydIsotropicProjection) {
      // sum_e k l_e^2 = 6 E V_t: the isotropic projection of the tet's tensor has modulus E.
      double sumL2 = 0.0;
      for (const auto& edge : kEdges) {
        const Vec3d d = positions[tet[edge[1]]] - positions[tet[edge[0]]];
        sumL2 += dot(d, d);
      }
      perEdge = 6.0 * e * volume / sumL2;
    }
    for (const auto& edge : kEdges) {
      const auto it = index.find(pairKey(tet[edge[0]], tet[edge[1]]));
      if (it == index.end())
        return Error{"tet " + std::to_string(t) + ": edge " + std::to_string(tet[edge[0]]) + "-" +
                     std::to_string(tet[edge[1]]) + " has no spring"};
      const double l = length(positions[tet[edge[1]]] - positions[tet[edge[0]]]);
      // Van Gelder 1998, 3D analogue of his membrane form: E V_t / l_e^2.
      k[it->second] += formula == TetStiffnessFormula::VanGelder1998 ? e * volume / (l * l) : perEdge;
      used[it->second] = 1;
    }
  }
  for (std::size_t s = 0; s < network.size(); ++s)
    if (!used[s])
      return Error{"spring " + std::to_string(s) + " (" + std::to_string(network.i[s]) + "-" +
                   std::to_string(network.j[s]) + ") is no tet edge"};
  store(network, k);
  return {};
}

LatticeSpringStiffness latticeInteriorStiffness(double youngsModulusKpa, double cellSizeMm) {
  // Isotropic with the Cauchy relation: lambda = mu, nu = 1/4, E = 5 mu / 2. With k3 = 0,
  // C12 = C44 = k2 / a = mu and C11 = (k1 + 2 k2) / a = 3 mu = lambda + 2 mu, so k1 = k2 = mu a.
  const double mu = 0.4 * kpaToNewtonPerMm2(youngsModulusKpa);  // N/mm^2
  return {.edge = mu * cellSizeMm, .faceDiagonal = mu * cellSizeMm, .bodyDiagonal = 0.0};
}

Result<void> setLatticeStiffness(EmbeddedLattice& lattice, const ElasticMaterial& material,
                                 LatticeBoundary boundary) {
  if (auto ok = validateMaterial(material); !ok) return ok;
  const LatticeSpringStiffness interior =
      latticeInteriorStiffness(material.youngsModulusKpa, lattice.cellSize);
  // An interior edge is shared by 4 cells, a face diagonal by 2, a body diagonal by 1: each cell
  // adds k1/4, k2/2 and k3, so that a cell's own springs carry the full target tensor.
  const double share[4] = {0.0, interior.edge / 4.0, interior.faceDiagonal / 2.0, interior.bodyDiagonal};
  const double whole[4] = {0.0, interior.edge, interior.faceDiagonal, interior.bodyDiagonal};
  SpringNetwork& network = lattice.springs;
  const auto index = springIndex(network);
  std::vector<double> k(network.size(), 0.0);
  std::vector<char> used(network.size(), 0);
  for (std::size_t c = 0; c < lattice.cells.size(); ++c) {
    const auto& cell = lattice.cells[c];
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b) {
        const auto it = index.find(pairKey(cell[a], cell[b]));
        if (it == index.end())
          return Error{"lattice cell " + std::to_string(c) + ": corners " + std::to_string(a) + " and " +
                       std::to_string(b) + " have no spring"};
        const int kind = std::popcount(static_cast<unsigned>(a ^ b));  // 1 edge, 2 face, 3 body
        if (boundary == LatticeBoundary::PerCell)
          k[it->second] += share[kind];
        else
          k[it->second] = whole[kind];
        used[it->second] = 1;
      }
  }
  for (std::size_t s = 0; s < network.size(); ++s)
    if (!used[s]) return Error{"lattice spring " + std::to_string(s) + " joins no two corners of a cell"};
  store(network, k);
  return {};
}

Result<void> setSurfaceStiffness(SpringNetwork& network, std::span<const Vec3d> positions,
                                 std::span<const Triangle> triangles, const ElasticMaterial& material,
                                 const ShellConfig& shell) {
  if (auto ok = validateMaterial(material); !ok) return ok;
  if (!(shell.thicknessMm > 0.0) || !std::isfinite(shell.thicknessMm))
    return Error{"thickness_mm: expected a positive number (mm), got " + shown(shell.thicknessMm)};
  if (!(shell.bendingFraction >= 0.0) || !std::isfinite(shell.bendingFraction))
    return Error{"bending_fraction: expected a number >= 0, got " + shown(shell.bendingFraction)};
  const double e = kpaToNewtonPerMm2(material.youngsModulusKpa);
  const auto index = springIndex(network);
  std::vector<double> k(network.size(), 0.0);
  std::vector<char> kind(network.size(), 0);  // 1 edge, 2 bending
  // Opposite vertices of each edge (for the bending springs).
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> opposite;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (std::uint32_t v : tri)
      if (v >= positions.size())
        return Error{"triangle " + std::to_string(t) + ": vertex " + std::to_string(v) + " out of range"};
    const Vec3d p0 = positions[tri[0]];
    const double area = 0.5 * length(cross(positions[tri[1]] - p0, positions[tri[2]] - p0));
    if (!(area > 0.0)) return Error{"triangle " + std::to_string(t) + ": zero area"};
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = tri[c], b = tri[(c + 1) % 3];
      const auto it = index.find(pairKey(a, b));
      if (it == index.end())
        return Error{"triangle " + std::to_string(t) + ": edge " + std::to_string(a) + "-" +
                     std::to_string(b) + " has no spring"};
      const double l = length(positions[b] - positions[a]);
      k[it->second] += e * shell.thicknessMm * area / (l * l);  // Van Gelder 1998: E t A_T / l^2
      kind[it->second] = 1;
      opposite[pairKey(a, b)].push_back(tri[(c + 2) % 3]);
    }
  }
  for (const auto& [edge, opp] : opposite) {
    if (opp.size() != 2) continue;
    const auto it = index.find(pairKey(opp[0], opp[1]));
    if (it == index.end() || kind[it->second] == 1) continue;
    k[it->second] = shell.bendingFraction * k[index.at(edge)];
    kind[it->second] = 2;
  }
  for (std::size_t s = 0; s < network.size(); ++s)
    if (!kind[s])
      return Error{"spring " + std::to_string(s) + " (" + std::to_string(network.i[s]) + "-" +
                   std::to_string(network.j[s]) + ") is neither a triangle edge nor a bending spring"};
  store(network, k);
  return {};
}

}  // namespace tissue::sim
