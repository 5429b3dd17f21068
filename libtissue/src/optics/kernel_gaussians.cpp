// d'Eon & Luebke's sum-of-Gaussians fit (GPU Gems 3 ch. 14; Freude eq. 4.15) and its kernel.
#include "tissue/optics/kernel_gaussians.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel_models.h"

namespace tissue::optics {
namespace {

// The fit's data: radii with 2D quadrature weights q = 2 pi r dr, and each channel's profile
// normalised to total 1.
struct FitData {
  Eigen::VectorXd r, q;
  std::array<Eigen::VectorXd, kChannels> y;
};

FitData sampleProfile(const RadialProfileRgb& profile) {
  // Geometric radii resolve the peak at r = 0 and the tail alike.
  const int m = 400;
  const double rHi = profile.radiusMm.back(), rLo = 1e-4 * rHi;
  FitData d;
  d.r.resize(m + 1);
  d.q.resize(m + 1);
  d.r(0) = 0.5 * rLo;  // the disc [0, rLo]
  d.q(0) = std::numbers::pi * rLo * rLo;
  for (int k = 0; k < m; ++k) {
    const double a = rLo * std::pow(rHi / rLo, double(k) / m),
                 b = rLo * std::pow(rHi / rLo, double(k + 1) / m);
    d.r(k + 1) = 0.5 * (a + b);
    d.q(k + 1) = std::numbers::pi * (b * b - a * a);
  }
  for (int c = 0; c < kChannels; ++c) {
    auto& y = d.y[static_cast<std::size_t>(c)];
    y.resize(m + 1);
    for (int k = 0; k <= m; ++k)
      y(k) = evaluateProfile(profile, c, d.r(k));
    y /= std::max(d.q.dot(y), 1e-300);
  }
  return d;
}

// Weights w >= 0 with sum 1 minimising sum_k q_k (B w - y)_k^2, by an active set on the KKT
// system; returns the residual.
double fitWeights(const Eigen::MatrixXd& b, const FitData& d, const Eigen::VectorXd& y, Eigen::VectorXd& w) {
  const Eigen::Index n = b.cols();
  std::vector<bool> active(static_cast<std::size_t>(n), true);
  const Eigen::MatrixXd bq = b.transpose() * d.q.asDiagonal();
  const Eigen::MatrixXd normal = bq * b;
  const Eigen::VectorXd rhs = bq * y;
  for (Eigen::Index round = 0; round <= n; ++round) {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < n; ++i)
      if (active[static_cast<std::size_t>(i)]) idx.push_back(i);
    const auto f = static_cast<Eigen::Index>(idx.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(f + 1, f + 1);
    Eigen::VectorXd v(f + 1);
    for (Eigen::Index i = 0; i < f; ++i) {
      for (Eigen::Index j = 0; j < f; ++j)
        kkt(i, j) = normal(idx[std::size_t(i)], idx[std::size_t(j)]);
      kkt(i, f) = kkt(f, i) = 1.0;
      v(i) = rhs(idx[std::size_t(i)]);
    }
    v(f) = 1.0;
    const Eigen::VectorXd s = kkt.completeOrthogonalDecomposition().solve(v);
    w = Eigen::VectorXd::Zero(n);
    Eigen::Index worst = -1;
    for (Eigen::Index i = 0; i < f; ++i) {
      w(idx[std::size_t(i)]) = s(i);
      if (s(i) < 0.0 && (worst < 0 || s(i) < w(worst))) worst = idx[std::size_t(i)];
    }
    if (worst < 0 || f == 1) break;
    active[static_cast<std::size_t>(worst)] = false;
  }
  w = w.cwiseMax(0.0);
  w /= w.sum();
  return (d.q.asDiagonal() * (b * w - y).cwiseAbs2()).sum();
}

Eigen::MatrixXd basis(const FitData& d, const Eigen::VectorXd& logV) {
  Eigen::MatrixXd b(d.r.size(), logV.size());
  for (Eigen::Index i = 0; i < logV.size(); ++i) {
    const double v = std::exp(logV(i));
    b.col(i) = ((-d.r.array().square()) / (2.0 * v)).exp() / (2.0 * std::numbers::pi * v);
  }
  return b;
}

double fitError(const FitData& d, const Eigen::VectorXd& logV) {
  const Eigen::MatrixXd b = basis(d, logV);
  double err = 0;
  Eigen::VectorXd w;
  for (const auto& y : d.y)
    err += fitWeights(b, d, y, w);
  return err;
}

// Nelder-Mead (standard coefficients) minimising fitError over log variances.
Eigen::VectorXd nelderMead(const FitData& d, Eigen::VectorXd x0, double step, int iterations) {
  const Eigen::Index n = x0.size();
  std::vector<Eigen::VectorXd> p{x0};
  for (Eigen::Index i = 0; i < n; ++i) {
    p.push_back(x0);
    p.back()(i) += step;
  }
  std::vector<double> f;
  for (const auto& x : p)
    f.push_back(fitError(d, x));
  for (int it = 0; it < iterations; ++it) {
    std::vector<std::size_t> o(p.size());
    for (std::size_t i = 0; i < o.size(); ++i)
      o[i] = i;
    std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
    const std::size_t best = o.front(), worst = o.back(), second = o[o.size() - 2];
    if (f[worst] - f[best] <= 1e-12 * (f[best] + 1e-300)) break;
    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i + 1 < o.size(); ++i)
      centroid += p[o[i]] / double(n);
    const Eigen::VectorXd xr = centroid + (centroid - p[worst]);
    const double fr = fitError(d, xr);
    if (fr < f[best]) {
      const Eigen::VectorXd xe = centroid + 2.0 * (centroid - p[worst]);
      const double fe = fitError(d, xe);
      p[worst] = fe < fr ? xe : xr;
      f[worst] = std::min(fe, fr);
    } else if (fr < f[second]) {
      p[worst] = xr;
      f[worst] = fr;
    } else {
      const Eigen::VectorXd xc = centroid + 0.5 * (p[worst] - centroid);
      const double fc = fitError(d, xc);
      if (fc < f[worst]) {
        p[worst] = xc;
        f[worst] = fc;
      } else {
        for (std::size_t i = 0; i < p.size(); ++i) {
          if (i == best) continue;
          p[i] = p[best] + 0.5 * (p[i] - p[best]);
          f[i] = fitError(d, p[i]);
        }
      }
    }
  }
  return p[static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin())];
}

}  // namespace

Result<GaussianSum> fitGaussians(const RadialProfileRgb& profile, int count) {
  if (count < 1 || count > 8)
    return Error{"fitGaussians('" + profile.name + "'): " + std::to_string(count) + " Gaussians; use 1..8"};
  if (profile.radiusMm.size() < 2 || !(profile.radiusMm.back() > 0.0))
    return Error{"fitGaussians('" + profile.name + "'): the profile needs samples out to r > 0 mm"};
  const FitData d = sampleProfile(profile);
  // Start: standard deviations spread geometrically over 1%..50% of the kernel half-width.
  const double w = profile.kernelHalfWidthMm;
  Eigen::VectorXd x(count);
  for (int i = 0; i < count; ++i) {
    const double t = count == 1 ? 0.5 : double(i) / (count - 1);
    x(i) = 2.0 * std::log(w * 0.01 * std::pow(50.0, t));
  }
  // Two rounds: a restart from the first optimum escapes a collapsed simplex.
  x = nelderMead(d, x, 1.0, 400 * count);
  x = nelderMead(d, x, 0.3, 400 * count);
  std::sort(x.data(), x.data() + count);
  const Eigen::MatrixXd b = basis(d, x);
  GaussianSum sum;
  for (int i = 0; i < count; ++i)
    sum.varianceMm2.push_back(std::exp(x(i)));
  for (int c = 0; c < kChannels; ++c) {
    Eigen::VectorXd wc;
    fitWeights(b, d, d.y[static_cast<std::size_t>(c)], wc);
    sum.weights[static_cast<std::size_t>(c)].assign(wc.data(), wc.data() + count);
  }
  return sum;
}

namespace detail {

std::vector<DenseComponent> gaussianComponents(const GroundTruthKernel& truth, const GaussianSum& sum) {
  // Each 2D Gaussian w G(v; x, y) = (sqrt(w) g(x)) (sqrt(w) g(y)) with g normalised on the line
  // (re-normalised on the grid, so the kernel keeps sum w = 1): one separable component each.
  std::vector<DenseComponent> out;
  const int n = truth.size();
  for (std::size_t i = 0; i < sum.varianceMm2.size(); ++i) {
    const double v = sum.varianceMm2[i] / (truth.cellMm * truth.cellMm);
    std::vector<double> g;
    double total = 0;
    for (int j = 0; j < n; ++j) {
      g.push_back(gaussianCellIntegral(j - truth.halfCells, v));
      total += g.back();
    }
    DenseComponent comp;
    for (std::size_t c = 0; c < kChannels; ++c) {
      const double s = std::sqrt(sum.weights[c][i]) / total;
      for (double x : g)
        comp.a[c].push_back(x * s);
    }
    out.push_back(std::move(comp));
  }
  return out;
}

}  // namespace detail
}  // namespace tissue::optics
