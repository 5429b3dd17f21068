// The manual two-Gaussian model (Freude 2014, §5.4, eq. 5.21; Table A.1).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "kernel_models.h"

namespace tissue::optics {
namespace {

struct TableRow {
  const char* name;
  ManualGaussians cm;  // Table A.1 as printed (cm)
};

// Freude Table A.1: sqrt(tau_n), sqrt(tau_f) per RGB channel and w. The thesis works in cm
// (Table 6.2); the widths fit the materials' scattering lengths only when read as cm.
constexpr TableRow kTableA1[] = {
    {"Apple", {{0.0495, 0.0455, 0.0372}, {1.1, 1.08, 0.926}, 0.368}},
    {"Ketchup", {{0.0907, 0.0331, 0.0331}, {1.5, 0.118, 0.0966}, 0.665}},
    {"Marble", {{0.0371, 0.0207, 0.015}, {0.663, 0.616, 0.558}, 0.234}},
    {"Skin1", {{0.429, 0.211, 0.03}, {1.15, 0.69, 0.471}, 0.533}},
    {"Wholemilk", {{0.0846, 0.0846, 0.0583}, {1.5, 1.39, 1.17}, 0.407}},
};

bool sameName(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  });
}

}  // namespace

Result<ManualGaussians> manualParameters(std::string_view material) {
  for (const auto& row : kTableA1) {
    if (!sameName(row.name, material)) continue;
    ManualGaussians mm = row.cm;
    for (int c = 0; c < kChannels; ++c) {
      mm.sigmaNearMm[static_cast<std::size_t>(c)] *= 10.0;
      mm.sigmaFarMm[static_cast<std::size_t>(c)] *= 10.0;
    }
    return mm;
  }
  return Error{
      "the manual model has parameters (Freude Table A.1) only for Apple, Ketchup, Marble, Skin1 and "
      "Wholemilk, not '" +
      std::string(material) + "'; pass KernelSettings::manual"};
}

namespace detail {

std::vector<DenseComponent> manualComponents(const GroundTruthKernel& truth, const ManualGaussians& p) {
  const int n = truth.size();
  DenseComponent comp;
  for (int c = 0; c < kChannels; ++c) {
    const auto ch = static_cast<std::size_t>(c);
    const double near = std::pow(p.sigmaNearMm[ch] / truth.cellMm, 2.0);  // variances in cells^2
    const double far = std::pow(p.sigmaFarMm[ch] / truth.cellMm, 2.0);
    auto& a = comp.a[ch];
    double sum = 0;
    for (int j = 0; j < n; ++j) {
      // Eq. 5.21: a_m = w G(tau_n) + (1 - w) G(tau_f), each G normalised on the line, so w is the
      // near Gaussian's share of the energy.
      const double x = j - truth.halfCells;
      const double v =
          p.nearWeight * gaussianCellIntegral(x, near) + (1.0 - p.nearWeight) * gaussianCellIntegral(x, far);
      a.push_back(v);
      sum += v;
    }
    // Freude: the model's energy is enforced by normalisation; here it corrects the truncation to
    // the grid, so that ||a a^T||_1 = 1 = ||R_d||_1.
    for (double& v : a)
      v /= sum;
  }
  return {comp};
}

}  // namespace detail
}  // namespace tissue::optics
