#pragma once
/// \file
/// Silhouette pixels of an MSAA frame read back (radiance alpha = coverage < 1) for the
/// screen-space references (sss-bench, the demo): such a pixel averages the surface with the
/// background, so it is no surface point for the reference, and a blurred value there is weighted
/// by its coverage for the tone map. GL-free (frames as render::FloatImage).

#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/renderer.h"

namespace tissue::studies {

/// Marks pixels only partly covered (radiance a < 0.999) as "no object" (w = id 0) in `diffuse`,
/// for frames whose resolve averaged their positions and ids with the background.
void dropPartialCoverage(std::vector<Float4>& diffuse, const render::FloatImage& radiance);

/// Divides the RGB of pixels partly covered (0 < radiance a < 1) by their coverage: the separable
/// blur weights silhouettes by coverage for the tone map, the reference convolves the surface's
/// own colour there.
void removeCoverageWeight(std::vector<Float4>& blurred, const render::FloatImage& radiance);

}  // namespace tissue::studies
