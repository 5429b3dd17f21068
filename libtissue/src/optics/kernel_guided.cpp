// Guided optimisation (Freude 2014, §5.3, eq. 5.19-5.20) with the 1-norm constraint held exactly.
//
// Freude put ||R_d||_1 = ||a||_1^2 into the objective as a soft penalty and reports up to 25%
// constraint error and 1-19 minutes per kernel. With a >= 0 and ||R_d||_1 = 1 the constraint is
// the linear equality sum(a) = 1, so we keep it exactly: Levenberg-Marquardt (Gauss-Newton on
// the residuals sqrt(Gamma) (R_d - a a^T)) whose every step solves the KKT system of the
// linearised problem with that equality, started from the pre-integrated kernel (which satisfies
// it). It converges in tens of iterations of one n x n Cholesky each.
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "kernel_models.h"

namespace tissue::optics::detail {
namespace {

// Eq. 5.20 on kernel space [-1, 1]^2: Gamma = (x^2 + y^2)^(k/2) (1 - e^(-b x^2)) (1 - e^(-b y^2)),
// the exponential terms left out for b = 0 (as Freude's implementation does).
Eigen::MatrixXd guideWeights(int halfCells, double k, double b) {
  const int n = 2 * halfCells + 1;
  Eigen::MatrixXd gamma(n, n);
  for (int i = 0; i < n; ++i) {
    const double y = (i - halfCells) / (halfCells + 0.5);
    for (int j = 0; j < n; ++j) {
      const double x = (j - halfCells) / (halfCells + 0.5);
      double g = std::pow(x * x + y * y, 0.5 * k);
      if (b > 0.0) g *= (1.0 - std::exp(-b * x * x)) * (1.0 - std::exp(-b * y * y));
      gamma(i, j) = g;
    }
  }
  return gamma;
}

// sum Gamma (R - a a^T)^2, without temporaries.
double objective(const Eigen::MatrixXd& gamma, const Eigen::MatrixXd& r, const Eigen::VectorXd& a) {
  double f = 0;
  for (Eigen::Index j = 0; j < a.size(); ++j) {
    for (Eigen::Index i = 0; i < a.size(); ++i) {
      const double e = r(i, j) - a(i) * a(j);
      f += gamma(i, j) * e * e;
    }
  }
  return f;
}

// Minimises the objective subject to sum(a) = 1 from a feasible start. The n x n work matrices
// are allocated once: fresh ones each iteration cost more in page faults than the arithmetic.
Eigen::VectorXd solveChannel(const Eigen::MatrixXd& gamma, const Eigen::MatrixXd& r, Eigen::VectorXd a) {
  const Eigen::Index n = a.size();
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
  Eigen::MatrixXd h(n, n), damped(n, n);
  Eigen::LLT<Eigen::MatrixXd> llt(n);
  Eigen::VectorXd g(n), diag(n), y(n), z(n), next(n);
  double f = objective(gamma, r, a);
  double lambda = 1e-3;
  for (int iter = 0; iter < 200 && lambda < 1e12; ++iter) {
    // Residual e = R - a a^T. Gradient/2 of the objective: g_k = -2 sum_j Gamma_kj e_kj a_j;
    // Gauss-Newton matrix H_kl = 2 delta_kl sum_j Gamma_kj a_j^2 + 2 Gamma_kl a_k a_l.
    g.setZero();
    for (Eigen::Index l = 0; l < n; ++l) {
      double diagonal = 0;
      for (Eigen::Index k = 0; k < n; ++k) {
        g(k) -= 2.0 * gamma(k, l) * (r(k, l) - a(k) * a(l)) * a(l);
        h(k, l) = 2.0 * gamma(k, l) * a(k) * a(l);
        diagonal += gamma(l, k) * a(k) * a(k);
      }
      diag(l) = diagonal;
    }
    h.diagonal() += 2.0 * diag;
    diag = h.diagonal().cwiseMax(1e-30);
    bool accepted = false;
    while (!accepted && lambda < 1e12) {
      damped = h;
      damped.diagonal() += lambda * diag;
      llt.compute(damped);
      if (llt.info() != Eigen::Success) {
        lambda *= 10.0;
        continue;
      }
      // KKT with the equality 1^T delta = 0: delta = y - mu z, H y = -g, H z = 1.
      y = llt.solve(-g);
      z = llt.solve(ones);
      next = a + y - (ones.dot(y) / ones.dot(z)) * z;
      const double fNext = objective(gamma, r, next);
      if (fNext < f) {
        const double gain = f - fNext;
        a = next;
        f = fNext;
        lambda = std::max(lambda / 3.0, 1e-12);
        accepted = true;
        if (gain <= 1e-9 * f) return a;  // converged: the error changes in its 9th digit
      } else {
        lambda *= 4.0;
      }
    }
  }
  return a;
}

}  // namespace

Result<std::vector<DenseComponent>> guidedComponents(const GroundTruthKernel& truth, double k, double b) {
  if (!(k >= 0.0) || !(b >= 0.0) || !std::isfinite(k + b))
    return Error{"guided kernel: k and b must be finite and >= 0 (eq. 5.20)"};
  const int n = truth.size();
  const Eigen::MatrixXd gamma = guideWeights(truth.halfCells, k, b);
  DenseComponent start = preIntegratedComponents(truth).front();
  DenseComponent out;
  for (int c = 0; c < kChannels; ++c) {
    const auto ch = static_cast<std::size_t>(c);
    Eigen::MatrixXd r(n, n);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        r(y, x) = truth.at(c, y, x);
    const double norm = r.sum();  // ||R_d||_1 (1 for a normalised ground truth)
    // Solve for a / sqrt(norm) against R_d / norm, so the equality is sum = 1.
    Eigen::VectorXd a = Eigen::Map<const Eigen::VectorXd>(start.a[ch].data(), n) / std::sqrt(norm);
    a = solveChannel(gamma, r / norm, a);
    // A kernel must not be negative; the optimum rarely is. Clamp, then hold the sum exactly.
    a = a.cwiseMax(0.0);
    if (!(a.sum() > 0.0) || !a.allFinite())
      return Error{"guided kernel of '" + truth.name + "': the optimisation failed in channel " +
                   std::to_string(c)};
    a *= std::sqrt(norm) / a.sum();
    out.a[ch].assign(a.data(), a.data() + n);
  }
  return std::vector<DenseComponent>{out};
}

}  // namespace tissue::optics::detail
