#pragma once
/// \file
/// The layered material of subsurface texture mapping (François et al. 2006, §2.1; Norberg
/// 2010, §2.1.2): N RGBA subsurface maps hold 4N layer-boundary depths per texel, each channel
/// the depth of one boundary below the surface along the normal (0..1 -> 0..depthScaleMm).
/// Layer i lies between boundary i - 1 (the surface for i = 0) and boundary i, so the 4N
/// boundaries bound 4N layers; a last, unbounded layer lies below the deepest boundary (the
/// project's data calls it "deep"). Each layer has its own sigma_s, sigma_t and g per RGB
/// channel (François Table 1). Lengths in mm, coefficients in mm^-1. GL-free.

#include <array>
#include <span>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::subsurface {

/// Most boundaries one stack may hold (two RGBA maps); the shader declares the same.
inline constexpr int kMaxBoundaries = 8;

/// Optical coefficients of one homogeneous layer.
struct LayerCoefficients {
  Float3 sigma_s{1.0f, 1.0f, 2.0f};  ///< scattering coefficient per RGB channel, mm^-1
  Float3 sigma_t{1.5f, 1.5f, 2.5f};  ///< extinction coefficient per RGB channel, mm^-1 (>= sigma_s)
  float g = 0.8f;                    ///< anisotropy (HG mean cosine), mapped to Schlick k = 1.55 g - 0.55 g^3
};

/// The boundary depths of N RGBA maps, as the GPU samples them: 8-bit values / 255.
struct SubsurfaceMaps {
  int width = 0;              ///< texels
  int height = 0;             ///< texels
  int mapCount = 0;           ///< N RGBA maps
  std::vector<float> depths;  ///< width * height * 4N, texel-major, rows top (v = 1) to bottom, 0..1
};

/// A whole layered material.
struct LayerStack {
  std::vector<LayerCoefficients> layers;  ///< 4N + 1 layers top first (or 1 with no maps: a half-space)
  SubsurfaceMaps maps;                    ///< the N maps (empty for a homogeneous half-space)
  float depthScaleMm = 3.0f;              ///< mm, the depth a subsurface value of 1 stands for
  int boundaryCount() const { return maps.mapCount * 4; }
};

/// Boundary depths at one texture coordinate.
struct Boundaries {
  std::array<float, kMaxBoundaries> depthMm{};  ///< mm below the surface, non-decreasing
  int count = 0;                                ///< 4N
};

/// Builds the maps from N RGBA images of one size (the files' rows, top = v 1). Errors say
/// which image is wrong.
Result<SubsurfaceMaps> subsurfaceMapsFromImages(std::span<const Image8> images);

/// Checks the stack: 4N + 1 layers, N <= 2, positive sigma_t >= sigma_s >= 0, |g| < 1.
Result<void> validateLayerStack(const LayerStack& stack);

/// The boundaries at texture coordinate `uv` (unitless, v up): bilinear between texel centres,
/// clamped at the edges, as GL_LINEAR with CLAMP_TO_EDGE on a texture uploaded bottom row first.
Boundaries sampleBoundaries(const LayerStack& stack, Float2 uv);

/// The layer that contains depth `depthMm` (mm): the number of boundaries at or above it.
/// Zero-thickness layers are skipped by construction.
int findLayer(const Boundaries& boundaries, float depthMm);

/// Thickness of layer `i` in mm (boundary i minus boundary i - 1; the last layer is unbounded).
float layerThicknessMm(const Boundaries& boundaries, int i);

}  // namespace tissue::subsurface
