// The pre-integrated kernel (Freude 2014, §5.2, eq. 5.17-5.18).
#include <cmath>

#include "kernel_models.h"

namespace tissue::optics::detail {

std::vector<DenseComponent> preIntegratedComponents(const GroundTruthKernel& truth) {
  const int n = truth.size();
  DenseComponent comp;
  for (int c = 0; c < kChannels; ++c) {
    auto& a = comp.a[static_cast<std::size_t>(c)];
    a.assign(static_cast<std::size_t>(n), 0.0);
    double norm = 0;  // ||R_d||_1
    // Eq. 5.17: a_p(x) = integral of R_d(x, y) dy (the column sums of the grid).
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        a[static_cast<std::size_t>(x)] += truth.at(c, y, x);
        norm += truth.at(c, y, x);
      }
    }
    // Eq. 5.18: a = a_p / sqrt(||R_d||_1), so ||a a^T||_1 = ||R_d||_1.
    const double scale = 1.0 / std::sqrt(norm);
    for (double& v : a)
      v *= scale;
  }
  return {comp};
}

}  // namespace tissue::optics::detail
