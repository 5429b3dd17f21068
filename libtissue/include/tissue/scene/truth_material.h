#pragma once
/// \file
/// The path-traced truth's material (tissue::truth::TruthMaterial) from the same material file
/// the renderer's methods read (material_file.h), so the truth renders the same organ: the same
/// layers (sigma_a = sigma_t - sigma_s, sigma_s, g per band), the file's ior for every layer,
/// and, with the subsurface map, the same per-texel boundaries (François et al. 2006 §2.1).
/// Lengths in mm, coefficients in mm^-1.

#include <span>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/scene/material_file.h"
#include "tissue/truth/material.h"

namespace tissue::scene {

/// `material` with its RGBA `subsurfaceMap` (the boundaries of its 4N + 1 layers) as the truth's
/// per-texel layered material under air. Errors name the file (a map that does not fit the
/// layer count, a layer the truth rejects).
Result<truth::TruthMaterial> truthMaterial(const MaterialFile& material, const Image8& subsurfaceMap);

/// `material` as constant-depth layers of `thicknessMm` (top first; the last is unbounded; one
/// fewer thickness than layers), for slabs and tests without a map. Errors name the file.
Result<truth::TruthMaterial> truthMaterial(const MaterialFile& material, std::span<const double> thicknessMm);

}  // namespace tissue::scene
