#pragma once
/// \file
/// The layered material of the path-traced truth: layers below the surface of a closed mesh,
/// each homogeneous with its own absorption, scattering, Henyey-Greenstein anisotropy and
/// refractive index per RGB band. A point inside the mesh lies at the depth of its distance to the
/// nearest surface point (mm); the layer boundaries are either constant depths (each layer's
/// thickness) or, per texel, the boundary depths of the subsurface maps at the nearest surface
/// point's texture coordinate (François et al. 2006, §2.1; tissue/subsurface/layer_stack.h).
/// Lengths in mm, coefficients in mm^-1. GL-free.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/medium.h"
#include "tissue/subsurface/layer_stack.h"

namespace tissue::truth {

/// Number of wavelength bands: red, green, blue (the renderer's linear RGB).
inline constexpr int kBands = 3;

/// One value per band, red first.
using Rgb = std::array<double, kBands>;

/// Thickness of a layer that extends to any depth (only the last layer may have it).
inline constexpr double kUnboundedMm = std::numeric_limits<double>::infinity();

/// One homogeneous layer. The coefficients have no defaults: a layer must state them.
struct TruthLayer {
  std::optional<Rgb> sigmaA;          ///< absorption coefficient per band, mm^-1 (required)
  std::optional<Rgb> sigmaS;          ///< scattering coefficient (not reduced) per band, mm^-1 (required)
  Rgb g{0.9, 0.9, 0.9};               ///< Henyey-Greenstein mean cosine per band, in (-1, 1)
  double n = 1.4;                     ///< refractive index (see TruthMaterial on interfaces)
  double thicknessMm = kUnboundedMm;  ///< mm (constant-depth layering); only the last may be unbounded
  std::string name;                   ///< optional, names the layer in error messages
};

/// Layers top first, under an ambient medium (air).
///
/// Interfaces: the outer surface refracts and reflects with the Fresnel equations between
/// `ambientN` and the top layer's n. Interfaces between layers are index-matched (no refraction or
/// reflection there): tissue layers differ in n by a few percent, which reflects ~1e-4 at normal
/// incidence; each layer's n is checked but only the top one's enters the transport.
struct TruthMaterial {
  std::vector<TruthLayer> layers;  ///< at least one, top first
  double ambientN = 1.0;           ///< refractive index outside the mesh
  /// Per-texel layering. Empty (mapCount 0): layer i spans the constant depths given by the
  /// thicknesses. Else its 4N boundary depths (0..1 times depthScaleMm, mm) replace the
  /// thicknesses, the material needs 4N + 1 layers and the mesh needs UVs.
  subsurface::SubsurfaceMaps maps;
  float depthScaleMm = 3.0f;  ///< mm, the depth a subsurface map value of 1 stands for
};

/// Checks the material; the Error names the layer, the field and how to fix it: a layer without
/// sigma_a or sigma_s, a non-finite or negative coefficient, |g| >= 1, n < 1, a thickness <= 0 or
/// non-finite before the last layer, a per-texel material with the wrong layer count.
Result<void> validateMaterial(const TruthMaterial& material);

/// The material of one band as the 1D Monte Carlo's slab stack (tissue::optics, constant depths
/// only): the same layers and indices, ambient above and below. For validation against MCML.
Result<optics::LayeredMedium> toLayeredMedium(const TruthMaterial& material, int band);

}  // namespace tissue::truth
