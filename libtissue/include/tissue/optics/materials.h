#pragma once
/// \file
/// The material library: Jensen et al. 2001's measured materials and d'Eon & Luebke's skin
/// Gaussians, parsed at run time from the TSV files the caller names
/// (shared/reference/jensen2001_materials.tsv, deon_skin_gaussians.tsv), and the project's layered
/// tissue materials (data/materials/*.json, first layer). Lengths in mm, coefficients in mm^-1.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/medium.h"

namespace tissue::optics {

/// RGB channel count of the materials.
inline constexpr int kChannels = 3;

/// A homogeneous scattering material, per RGB channel.
struct ScatteringMaterial {
  std::string name;
  std::array<double, kChannels> sigmaA{};  ///< absorption, mm^-1
  std::array<double, kChannels> sigmaS{};  ///< scattering (not reduced), mm^-1
  double g = 0.0;                          ///< HG anisotropy (Jensen's table: 0, sigma_s = sigma_s')
  double eta = 1.3;                        ///< relative index of refraction to the ambient
  std::string source;                      ///< where the numbers come from

  /// Reduced scattering sigma_s (1 - g) of `channel`, mm^-1.
  double sigmaSPrime(int channel) const { return sigmaS[channel] * (1.0 - g); }
};

/// Parses the Jensen 2001 table (columns material, sps_R/G/B, sa_R/G/B, eta; '#' comments).
/// Errors name the file and line.
Result<std::vector<ScatteringMaterial>> loadJensenMaterials(const std::filesystem::path& tsv);

/// Finds `name` in `materials`, ignoring ASCII case ("skin1" finds "Skin1"). The error lists the names.
Result<ScatteringMaterial> findMaterial(const std::vector<ScatteringMaterial>& materials,
                                        std::string_view name);

/// One channel of `material` as a half-space below an ambient of index 1 and the layer index eta.
LayeredMedium halfSpace(const ScatteringMaterial& material, int channel);

/// A sum of Gaussians R(r) = sum_i w_i exp(-r^2 / (2 v_i)) / (2 pi v_i), per channel.
struct GaussianSum {
  std::vector<double> varianceMm2;                     ///< v_i, mm^2
  std::array<std::vector<double>, kChannels> weights;  ///< w_i per channel
};

/// Parses d'Eon & Luebke's skin Gaussians (columns variance_mm2, w_R, w_G, w_B).
Result<GaussianSum> loadDeonGaussians(const std::filesystem::path& tsv);

/// R(r) of `channel`, mm^-2, at radius `r` in mm.
double gaussianSumProfile(const GaussianSum& sum, int channel, double r);

}  // namespace tissue::optics
