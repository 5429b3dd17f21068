// The network's stiffness matrix at rest (see linear_stiffness.h).
#include "linear_stiffness.h"

#include "tissue/sim/units.h"

namespace tissue::sim::detail {

/// k n n^T of spring s (N/mm) at the rest positions.
static std::array<double, 9> springBlock(const SpringNetwork& network, std::span<const Vec3d> rest,
                                         std::size_t s) {
  const Vec3d d = rest[network.j[s]] - rest[network.i[s]];
  const Vec3d n = (1.0 / length(d)) * d;
  const double k = network.stiffness[s] / kStiffnessPerNewtonPerMm;
  const double c[3] = {n.x, n.y, n.z};
  std::array<double, 9> b{};
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q)
      b[3 * r + q] = k * c[r] * c[q];
  return b;
}

FreeSystem assembleFree(const SpringNetwork& network, std::span<const Vec3d> rest,
                        const std::vector<char>& held, std::span<const std::uint32_t> vertexOrder) {
  FreeSystem sys;
  sys.freeIndex.assign(held.size(), -1);
  int rows = 0;
  const std::size_t vertices = held.size() / 3;
  for (std::size_t o = 0; o < vertices; ++o) {
    const std::size_t v = vertexOrder.empty() ? o : vertexOrder[o];
    for (std::size_t a = 0; a < 3; ++a)
      if (!held[3 * v + a]) sys.freeIndex[3 * v + a] = rows++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(network.size() * 36);
  for (std::size_t s = 0; s < network.size(); ++s) {
    const auto b = springBlock(network, rest, s);
    const std::uint32_t ends[2] = {network.i[s], network.j[s]};
    for (int p = 0; p < 2; ++p)
      for (int q = 0; q < 2; ++q)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            const int row = sys.freeIndex[3 * ends[p] + r], col = sys.freeIndex[3 * ends[q] + c];
            if (row >= 0 && col >= 0) triplets.emplace_back(row, col, (p == q ? 1.0 : -1.0) * b[3 * r + c]);
          }
  }
  sys.k.resize(rows, rows);
  sys.k.setFromTriplets(triplets.begin(), triplets.end());
  return sys;
}

/// (K u) per degree of freedom (N): the force the supports must apply to hold `u` (mm).
std::vector<double> stiffnessTimes(const SpringNetwork& network, std::span<const Vec3d> rest,
                                   std::span<const Vec3d> u) {
  std::vector<double> f(3 * u.size(), 0.0);
  for (std::size_t s = 0; s < network.size(); ++s) {
    const auto b = springBlock(network, rest, s);
    const Vec3d du = u[network.i[s]] - u[network.j[s]];
    const double v[3] = {du.x, du.y, du.z};
    for (int r = 0; r < 3; ++r) {
      const double fr = b[3 * r] * v[0] + b[3 * r + 1] * v[1] + b[3 * r + 2] * v[2];
      f[3 * network.i[s] + r] += fr;
      f[3 * network.j[s] + r] -= fr;
    }
  }
  return f;
}

namespace {

void dissect(const std::array<int, 3>& lo, const std::array<int, 3>& hi, const std::array<int, 3>& cells,
             std::vector<std::uint32_t>& out) {
  // Node box [lo, hi] inclusive.
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
  auto emit = [&](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int i = a[0]; i <= b[0]; ++i)
          out.push_back(static_cast<std::uint32_t>(i + (cells[0] + 1) * (j + (cells[1] + 1) * k)));
  };
  if (hi[axis] - lo[axis] < 2) {
    emit(lo, hi);
    return;
  }
  const int mid = (lo[axis] + hi[axis]) / 2;
  std::array<int, 3> leftHi = hi, rightLo = lo, planeLo = lo, planeHi = hi;
  leftHi[axis] = mid - 1;
  rightLo[axis] = mid + 1;
  planeLo[axis] = planeHi[axis] = mid;
  dissect(lo, leftHi, cells, out);
  dissect(rightLo, hi, cells, out);
  emit(planeLo, planeHi);
}

}  // namespace

std::vector<std::uint32_t> nestedDissectionOrder(std::array<int, 3> cells) {
  std::vector<std::uint32_t> out;
  out.reserve(std::size_t(cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1));
  dissect({0, 0, 0}, cells, cells, out);
  return out;
}

}  // namespace tissue::sim::detail
