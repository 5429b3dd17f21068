// Rank-R SVD kernels (Freude 2014, §5.1, eq. 5.5-5.12), with Eigen's divide-and-conquer SVD.
#include <Eigen/SVD>
#include <cmath>

#include "kernel_models.h"

namespace tissue::optics::detail {

Result<std::vector<DenseComponent>> svdComponents(const GroundTruthKernel& truth, int rank, bool normalize) {
  const int n = truth.size();
  std::vector<DenseComponent> out(static_cast<std::size_t>(rank));
  for (int c = 0; c < kChannels; ++c) {
    const auto& v = truth.values[static_cast<std::size_t>(c)];
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> m(v.data(),
                                                                                                     n, n);
    // Eq. 5.4: R_d = U Sigma V^T; eq. 5.5: keep the first R singular values.
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinU | Eigen::ComputeThinV);
    if (svd.info() != Eigen::Success) return Error{"SVD of the '" + truth.name + "' kernel did not converge"};
    for (int i = 0; i < rank; ++i) {
      // Eq. 5.8/5.10: a_i = u_i sqrt(sigma_i). R_d is symmetric, so v_i = +-u_i; the sign is that
      // of the eigenvalue (always + for i = 0 by Perron-Frobenius, R_d being positive).
      Eigen::VectorXd a = svd.matrixU().col(i) * std::sqrt(svd.singularValues()(i));
      const double sign = svd.matrixU().col(i).dot(svd.matrixV().col(i)) < 0.0 ? -1.0 : 1.0;
      if (a.sum() < 0.0) a = -a;  // a a^T is unchanged; keep the taps mostly positive
      auto& comp = out[static_cast<std::size_t>(i)];
      comp.sign[static_cast<std::size_t>(c)] = sign;
      comp.a[static_cast<std::size_t>(c)].assign(a.data(), a.data() + n);
    }
  }
  if (normalize) {
    // Eq. 5.12: scale A to the ground truth's 1-norm (1). We scale by the kernel's sum (its DC
    // gain), which is its 1-norm wherever A >= 0 and is what a blur must keep to conserve energy.
    for (int c = 0; c < kChannels; ++c) {
      const auto ch = static_cast<std::size_t>(c);
      double gain = 0;
      for (const auto& comp : out) {
        double s = 0;
        for (double x : comp.a[ch])
          s += x;
        gain += comp.sign[ch] * s * s;
      }
      if (!(gain > 0.0)) return Error{"SVD kernel of '" + truth.name + "' has no positive sum to normalise"};
      const double scale = 1.0 / std::sqrt(gain);
      for (auto& comp : out)
        for (double& x : comp.a[ch])
          x *= scale;
    }
  }
  return out;
}

}  // namespace tissue::optics::detail
