#pragma once
/// \file
/// The shading methods: a closed set (STYLE.md rule 5), one enum and one variant of per-method
/// settings. An object's method is the variant's alternative; `shadingMethod()` names it, and
/// the pipeline switches on it once per object. Lengths are mm.

#include <string_view>
#include <variant>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// How an object is shaded. The order matches MethodSettings' alternatives.
enum class ShadingMethod { Lit, Separable, TextureSpace, RayMarch, Parallax };

/// Blinn-Phong through the normal map, straight into the HDR target. No subsurface scattering.
struct LitSettings {};

/// Screen-space separable subsurface scattering (Jimenez et al. 2015; Freude 2014, ch. 4):
/// diffuse and specular go to separate targets, the diffuse is blurred by two 1D passes with
/// this object's kernel, scaled per pixel (Freude eq. 4.11) and following the surface
/// (eq. 4.12); the specular is added after the blur.
struct SeparableSettings {
  /// The 1D kernel: {w_R, w_G, w_B, offset_mm} per tap, unitless weights (each channel sums to
  /// 1 for an energy-conserving kernel), offsets in mm on the surface. Up to kMaxKernelTaps.
  std::vector<Float4> kernel;
  /// Depth difference (mm, along the view ray) at which a tap is fully replaced by the centre
  /// colour (follow-surface, eq. 4.12: t = |i_d - o_d| / followSurfaceMm). 0: the kernel's
  /// largest |offset|.
  float followSurfaceMm = 0.0f;
  bool followSurface = true;  ///< eq. 4.12 on or off
  /// Transmittance through thin parts (Jimenez et al. 2010, translucency): {T_R, T_G, T_B,
  /// thickness_mm} rows with increasing thickness, linearly interpolated; empty = none. T is
  /// the unitless fraction of irradiance leaving the back side after crossing thickness_mm.
  std::vector<Float4> transmittance;
  /// mm the shading point is pushed inside along -N before the thickness lookup (avoids the
  /// surface's own shadow-map depth).
  float transmissionShrinkMm = 0.5f;
};

/// Texture-space diffusion (d'Eon et al. 2007). Not in this build: branch `tsd`.
struct TextureSpaceSettings {};
/// Ray-marched subsurface texture mapping (François et al.). Not in this build: branch `raymarch`.
struct RayMarchSettings {};
/// Layered parallax mapping. Not in this build: branch `raymarch`.
struct ParallaxSettings {};

/// Per-object settings; the alternative chosen is the object's shading method.
using MethodSettings =
    std::variant<LitSettings, SeparableSettings, TextureSpaceSettings, RayMarchSettings, ParallaxSettings>;

/// The most taps a separable kernel may have.
inline constexpr int kMaxKernelTaps = 64;
/// The most transmittance rows of a separable material.
inline constexpr int kMaxTransmittanceRows = 16;

/// The method an object's settings select.
inline ShadingMethod shadingMethod(const MethodSettings& settings) {
  return static_cast<ShadingMethod>(settings.index());
}

/// A stable lower-case name ("lit", "separable", "texture-space", "ray-march", "parallax").
std::string_view shadingMethodName(ShadingMethod method);

}  // namespace tissue::render
