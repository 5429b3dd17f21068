// Importance sampling of a dense 1D kernel into shader taps (kernel_models.h).
#include <algorithm>
#include <cmath>

#include "kernel_models.h"

namespace tissue::optics::detail {
namespace {

// The positive half axis x >= 0 (in cells) as piecewise-constant segments: [0, 1/2] holds half
// of the centre cell, [d - 1/2, d + 1/2] cell h + d. density[s][c]: channel c, [s][3]: sum of |a|.
struct HalfAxis {
  std::vector<double> edge;  // segment s spans [edge[s], edge[s + 1]]
  std::vector<std::array<double, 4>> density;

  // Integral over [x0, x1] of channel `c` (3: the combined |a|) times x^moment (0 or 1).
  double integral(int c, double x0, double x1, int moment) const {
    double sum = 0;
    for (std::size_t s = 0; s + 1 < edge.size(); ++s) {
      const double a = std::max(x0, edge[s]), b = std::min(x1, edge[s + 1]);
      if (b <= a) continue;
      const double p = density[s][static_cast<std::size_t>(c)];
      sum += moment == 0 ? p * (b - a) : p * 0.5 * (b * b - a * a);
    }
    return sum;
  }

  // The x at which the combined mass from 0 reaches `target`.
  double quantile(double target) const {
    double mass = 0;
    for (std::size_t s = 0; s + 1 < edge.size(); ++s) {
      const double seg = density[s][3] * (edge[s + 1] - edge[s]);
      if (mass + seg >= target && seg > 0.0) return edge[s] + (target - mass) / density[s][3];
      mass += seg;
    }
    return edge.back();
  }
};

HalfAxis makeHalfAxis(const DenseComponent& component) {
  const int n = static_cast<int>(component.a[0].size());
  const int h = (n - 1) / 2;
  HalfAxis axis;
  axis.edge.push_back(0.0);
  for (int d = 0; d <= h; ++d) {
    axis.edge.push_back(d + 0.5);
    std::array<double, 4> p{};
    for (std::size_t c = 0; c < kChannels; ++c) {
      // Mirror-average: the components are symmetric up to rounding.
      p[c] = 0.5 * (component.a[c][static_cast<std::size_t>(h + d)] +
                    component.a[c][static_cast<std::size_t>(h - d)]);
      p[3] += std::abs(p[c]);
    }
    axis.density.push_back(p);
  }
  return axis;
}

KernelTap makeTap(const HalfAxis& axis, double x0, double x1, double offsetCells, double cellMm,
                  double factor) {
  KernelTap tap;
  tap.offsetMm = static_cast<float>(offsetCells * cellMm);
  tap.weight = {static_cast<float>(factor * axis.integral(0, x0, x1, 0)),
                static_cast<float>(factor * axis.integral(1, x0, x1, 0)),
                static_cast<float>(factor * axis.integral(2, x0, x1, 0))};
  return tap;
}

}  // namespace

std::vector<KernelTap> sampleTaps(const DenseComponent& component, double cellMm, int taps) {
  const int n = static_cast<int>(component.a[0].size());
  const int h = (n - 1) / 2;
  std::vector<KernelTap> out;
  if (taps >= n) {  // one tap per cell: the dense kernel itself
    out.push_back({{static_cast<float>(component.a[0][static_cast<std::size_t>(h)]),
                    static_cast<float>(component.a[1][static_cast<std::size_t>(h)]),
                    static_cast<float>(component.a[2][static_cast<std::size_t>(h)])},
                   0.f});
    for (int j = 0; j < n; ++j) {
      if (j == h) continue;
      const auto i = static_cast<std::size_t>(j);
      out.push_back({{static_cast<float>(component.a[0][i]), static_cast<float>(component.a[1][i]),
                      static_cast<float>(component.a[2][i])},
                     static_cast<float>((j - h) * cellMm)});
    }
    return out;
  }
  // Equal shares of the combined |a|: the centre's span [-x, x] and K spans on each side, each
  // holding 2T/taps of the total 2T; a tap sits at its span's centroid (exact first moment) and
  // weighs the integral of a over the span (the weights keep the sum exactly).
  const HalfAxis axis = makeHalfAxis(component);
  const int k = (taps - 1) / 2;
  const double total = axis.integral(3, 0.0, axis.edge.back(), 0);
  std::vector<double> bounds{0.0};
  for (int i = 0; i <= k; ++i)
    bounds.push_back(i == k ? axis.edge.back() : axis.quantile(total * (1.0 + 2.0 * i) / taps));
  out.push_back(makeTap(axis, 0.0, bounds[1], 0.0, cellMm, 2.0));
  std::vector<KernelTap> side;
  for (int i = 1; i <= k; ++i) {
    const double x0 = bounds[static_cast<std::size_t>(i)], x1 = bounds[static_cast<std::size_t>(i + 1)];
    const double mass = axis.integral(3, x0, x1, 0);
    const double centroid = mass > 0.0 ? axis.integral(3, x0, x1, 1) / mass : 0.5 * (x0 + x1);
    side.push_back(makeTap(axis, x0, x1, centroid, cellMm, 1.0));
  }
  for (auto it = side.rbegin(); it != side.rend(); ++it) {
    KernelTap neg = *it;
    neg.offsetMm = -neg.offsetMm;
    out.push_back(neg);
  }
  out.insert(out.end(), side.begin(), side.end());
  return out;
}

double gaussianCellIntegral(double xCells, double varianceCells2) {
  const double s = std::sqrt(2.0 * varianceCells2);
  return 0.5 * (std::erf((xCells + 0.5) / s) - std::erf((xCells - 0.5) / s));
}

}  // namespace tissue::optics::detail
