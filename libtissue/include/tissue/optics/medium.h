#pragma once
/// \file
/// A stack of plane-parallel slabs, MCML's geometry (Wang & Jacques, MCML manual): the light
/// enters at z = 0 and z grows into the tissue. Lengths in mm, coefficients in mm^-1.

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::optics {

/// Thickness of a layer that extends to z = infinity (only the last layer may have it).
inline constexpr double kInfiniteThickness = std::numeric_limits<double>::infinity();

/// One homogeneous slab.
struct Layer {
  double n = 1.4;                         ///< refractive index
  double mua = 0.1;                       ///< absorption coefficient, mm^-1
  double mus = 9.9;                       ///< scattering coefficient (not reduced), mm^-1
  double g = 0.9;                         ///< Henyey-Greenstein anisotropy, mean cosine in (-1, 1)
  double thickness = kInfiniteThickness;  ///< mm, or kInfiniteThickness
};

/// Layers top first, between an ambient medium above and one below.
struct LayeredMedium {
  double ambientAbove = 1.0;  ///< refractive index above z = 0
  double ambientBelow = 1.0;  ///< refractive index below the last layer (unused if it is infinite)
  std::vector<Layer> layers;  ///< at least one
};

/// Checks ranges: n >= 1, mua, mus >= 0, |g| < 1, thickness > 0, only the last layer infinite.
/// The error names the layer and the field.
Result<void> validateMedium(const LayeredMedium& medium);

/// Parses a medium file's text: {"ambient_n": 1.0, "ambient_n_below": 1.0 (optional, default
/// ambient_n), "layers": [{"n", "mua", "mus", "g", "thickness": mm or "inf"}]} with mua, mus in
/// mm^-1. Unknown keys are errors. `source` names the file in error messages.
Result<LayeredMedium> parseMediumJson(const std::string& text, const std::string& source);

/// Reads and parses a medium file (see parseMediumJson).
Result<LayeredMedium> loadMediumFile(const std::filesystem::path& path);

/// Specular reflectance at normal incidence from the ambient into the first layer,
/// ((n1 - n2) / (n1 + n2))^2 (as MCML; glass layers are not treated specially).
double specularReflectance(const LayeredMedium& medium);

}  // namespace tissue::optics
