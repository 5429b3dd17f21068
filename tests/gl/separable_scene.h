#pragma once
// Shared pieces of the separable SSS tests: Gaussian kernels, a fronto-parallel camera and
// region means of read-back frames. Lengths in mm.
#include <vector>

#include "tissue/core/image.h"
#include "tissue/reference/screen_convolution.h"
#include "tissue/render/renderer.h"

namespace tissue::test {

/// A Gaussian of standard deviation `sigmaMm` (all channels): `taps` taps evenly spaced over
/// +-3 sigma, weights normalised to sum 1 ({w_R, w_G, w_B, offset_mm}).
std::vector<Float4> gaussianTaps(float sigmaMm, int taps);

/// The 2D Gaussian a rank-1 Gaussian kernel separates, tabulated to 4 sigma for the CPU reference.
reference::RadialProfile gaussianProfile(float sigmaMm);

/// Camera on +z at 200 mm looking at the origin; a directional light straight down -z.
render::Scene frontScene();

/// An object of `mesh` shaded with the separable method.
render::SceneObject separableObject(render::MeshHandle mesh, render::SeparableSettings settings);

/// frontScene() with one separable object: a 200 mm patch at z = 0 that fills the view, with
/// base colour `texture`, both uploaded to `renderer`.
Result<render::Scene> texturedPatchScene(render::Renderer& renderer, const Image8& texture,
                                         render::SeparableSettings settings);

/// The mean of channel `channel` (0 R, 1 G, 2 B) over pixels [x0, x1) x [y0, y1).
double meanOver(const render::FloatImage& image, int x0, int x1, int y0, int y1, int channel = 0);

}  // namespace tissue::test
