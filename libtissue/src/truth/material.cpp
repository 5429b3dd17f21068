// Validation of the truth's layered material, and its 1D form for the slab Monte Carlo.
#include "tissue/truth/material.h"

#include <cmath>
#include <string>

namespace tissue::truth {
namespace {

std::string layerName(const TruthMaterial& m, std::size_t i) {
  std::string s = "truth material: layer " + std::to_string(i);
  if (!m.layers[i].name.empty()) s += " (\"" + m.layers[i].name + "\")";
  return s;
}

const char* bandName(int band) {
  static const char* names[kBands] = {"red", "green", "blue"};
  return names[band];
}

// One coefficient triple: present, finite, >= 0.
Result<void> checkCoefficients(const TruthMaterial& m, std::size_t i, const std::optional<Rgb>& rgb,
                               const char* field) {
  if (!rgb)
    return Error{layerName(m, i) + " has no " + field + ": give " + field +
                 " in mm^-1 for the red, green and blue bands"};
  for (int b = 0; b < kBands; ++b) {
    const double v = (*rgb)[static_cast<std::size_t>(b)];
    if (!std::isfinite(v) || v < 0.0)
      return Error{layerName(m, i) + ": " + field + " (" + bandName(b) + ") = " + std::to_string(v) +
                   " mm^-1; it must be finite and >= 0"};
  }
  return {};
}

}  // namespace

Result<void> validateMaterial(const TruthMaterial& m) {
  if (m.layers.empty()) return Error{"truth material: no layers; give at least one layer (top first)"};
  if (!std::isfinite(m.ambientN) || m.ambientN < 1.0)
    return Error{"truth material: ambient refractive index " + std::to_string(m.ambientN) + " must be >= 1"};
  const bool perTexel = m.maps.mapCount > 0;
  for (std::size_t i = 0; i < m.layers.size(); ++i) {
    const TruthLayer& layer = m.layers[i];
    if (auto ok = checkCoefficients(m, i, layer.sigmaA, "sigma_a"); !ok) return ok;
    if (auto ok = checkCoefficients(m, i, layer.sigmaS, "sigma_s"); !ok) return ok;
    for (int b = 0; b < kBands; ++b) {
      const double g = layer.g[static_cast<std::size_t>(b)];
      if (!std::isfinite(g) || std::abs(g) >= 1.0)
        return Error{layerName(m, i) + ": g (" + bandName(b) + ") = " + std::to_string(g) +
                     "; the Henyey-Greenstein mean cosine must lie in (-1, 1)"};
    }
    if (!std::isfinite(layer.n) || layer.n < 1.0)
      return Error{layerName(m, i) + ": refractive index n = " + std::to_string(layer.n) + " must be >= 1"};
    if (perTexel) continue;  // the maps give the depths
    const bool last = i + 1 == m.layers.size();
    const double d = layer.thicknessMm;
    if (std::isnan(d) || d <= 0.0)
      return Error{layerName(m, i) + ": thickness " + std::to_string(d) +
                   " mm must be > 0; give its depth extent below the layer above in mm"};
    if (!last && !std::isfinite(d))
      return Error{layerName(m, i) +
                   " is unbounded but not the last layer; give it a finite thickness in mm"};
  }
  if (perTexel) {
    const std::size_t want = static_cast<std::size_t>(m.maps.mapCount) * 4 + 1;
    if (m.maps.mapCount > subsurface::kMaxBoundaries / 4)
      return Error{"truth material: " + std::to_string(m.maps.mapCount) + " subsurface maps; at most " +
                   std::to_string(subsurface::kMaxBoundaries / 4) + " are supported"};
    if (m.layers.size() != want)
      return Error{"truth material: " + std::to_string(m.maps.mapCount) + " subsurface maps bound " +
                   std::to_string(want) + " layers, but " + std::to_string(m.layers.size()) +
                   " are given; give 4N + 1 layers for N maps"};
    if (m.maps.width < 1 || m.maps.height < 1 ||
        m.maps.depths.size() != std::size_t(m.maps.width) * m.maps.height * (want - 1))
      return Error{"truth material: the subsurface maps' depth array does not match width * height * 4N"};
    if (!std::isfinite(m.depthScaleMm) || m.depthScaleMm <= 0.0f)
      return Error{"truth material: depth scale " + std::to_string(m.depthScaleMm) + " mm must be > 0"};
  }
  return {};
}

Result<optics::LayeredMedium> toLayeredMedium(const TruthMaterial& m, int band) {
  if (auto ok = validateMaterial(m); !ok) return ok.error();
  if (band < 0 || band >= kBands)
    return Error{"truth material: band " + std::to_string(band) + " is not 0, 1 or 2"};
  if (m.maps.mapCount > 0)
    return Error{"truth material: per-texel layering has no 1D slab form; use constant thicknesses"};
  optics::LayeredMedium medium;
  medium.ambientAbove = m.ambientN;
  medium.ambientBelow = m.ambientN;
  const auto b = static_cast<std::size_t>(band);
  for (const TruthLayer& layer : m.layers)
    medium.layers.push_back(
        {.n = layer.n,
         .mua = (*layer.sigmaA)[b],
         .mus = (*layer.sigmaS)[b],
         .g = layer.g[b],
         .thickness = std::isfinite(layer.thicknessMm) ? layer.thicknessMm : optics::kInfiniteThickness});
  return medium;
}

}  // namespace tissue::truth
