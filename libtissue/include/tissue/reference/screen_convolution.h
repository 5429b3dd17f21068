#pragma once
/// \file
/// CPU reference of screen-space subsurface scattering: the exact 2D convolution, on the
/// surface in world space, of a frame's diffuse radiance with a material's radial diffusion
/// profile R(r). It works on plain arrays read back from a renderer (per-pixel radiance with an
/// object id, per-pixel world positions) and never includes GL, so a renderer's screen-space
/// approximation (e.g. Jimenez's separable blur, Freude 2014 ch. 4) can be measured against it.
/// Lengths in mm, R in mm^-2.

#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::reference {

/// A radial profile tabulated at increasing radii from 0: R(r) per RGB channel, mm^-2, linear
/// between samples and 0 beyond the last radius.
struct RadialProfile {
  std::vector<float> radiusMm;  ///< increasing, the first 0, mm
  std::vector<Float3> value;    ///< R(r_i) per channel, mm^-2
  bool empty() const { return radiusMm.empty(); }
};

/// The profile's integral over the disc of radius `rMm`: int_0^r R(r') 2 pi r' dr' per channel
/// (exact for the piecewise-linear R). Over the whole table: the total diffuse reflectance.
Float3 profileIntegral(const RadialProfile& profile, float rMm);

/// The profile scaled to integrate to 1 per channel over the plane (its shape).
RadialProfile normalizedProfile(const RadialProfile& profile);

/// One frame as read back: `width` x `height` pixels, rows top to bottom.
struct ScreenBuffers {
  int width = 0;
  int height = 0;
  std::span<const Float4> radiance;  ///< RGB to convolve; a = object id (0 = nothing)
  std::span<const Float4> position;  ///< world xyz, mm (meaningful where the id is non-zero)
};

/// The convolution out(p) = sum_q radiance(q) int_{footprint(q)} R_id(|x_p - x|) dA over the
/// pixels q of p's own object (ids never mix). A pixel's footprint is its world-space
/// parallelogram spanned by the position differences to its same-object neighbours; the own
/// pixel integrates R over the disc of its footprint's area, pixels within 2 of p integrate
/// over a 4 x 4 grid of their footprint, farther ones take R at the centre times the area.
/// `profiles[id]` is object id's profile (an empty profile: the pixel is copied through).
/// Returns RGB per pixel; pixels without an object are 0.
Result<std::vector<Float3>> convolveScreen(const ScreenBuffers& frame,
                                           std::span<const RadialProfile> profiles);

/// RMS difference between `actual` (RGB of a renderer's result, a ignored) and `reference`
/// over the pixels whose id has a non-empty profile, all three channels.
struct ImageError {
  double rms = 0.0;            ///< same units as the radiance
  double meanReference = 0.0;  ///< mean of the reference over the same pixels and channels
  double relativeRms = 0.0;    ///< rms / meanReference
  std::size_t pixels = 0;      ///< pixels compared
};

/// Compares a renderer's blurred result with convolveScreen's output on the same frame.
ImageError compareWithReference(const ScreenBuffers& frame, std::span<const Float4> actual,
                                std::span<const Float3> reference, std::span<const RadialProfile> profiles);

}  // namespace tissue::reference
