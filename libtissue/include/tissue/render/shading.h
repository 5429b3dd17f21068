#pragma once
/// \file
/// The shading methods: a closed set (STYLE.md rule 5), one enum and one variant of per-method
/// settings. An object's method is the variant's alternative; `shadingMethod()` names it, and
/// the pipeline switches on it once per object. Lengths are mm.

#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// How an object is shaded. The order matches MethodSettings' alternatives.
enum class ShadingMethod { Lit, Separable, TextureSpace, RayMarch, Parallax };

/// Blinn-Phong through the normal map, straight into the HDR target. No subsurface scattering.
struct LitSettings {};

/// One component a_r of a separable kernel (Freude eq. 5.10): the diffuse is blurred
/// horizontally, then vertically, with the same taps, and the result is multiplied by `sign`.
struct SeparableComponent {
  /// The 1D taps: {w_R, w_G, w_B, offset_mm} each, unitless weights, offsets in mm on the
  /// surface. 1..kMaxKernelTaps.
  std::vector<Float4> taps;
  /// Per channel (R, G, B): +1, or -1 for an SVD component of a negative eigenvalue (Freude
  /// eq. 5.8-5.10). Any finite factor is applied as given.
  Float3 sign{1.0f, 1.0f, 1.0f};
};

/// Screen-space separable subsurface scattering (Jimenez et al. 2015; Freude 2014, ch. 4):
/// diffuse and specular go to separate targets, the diffuse is blurred by two 1D passes per
/// kernel component, scaled per pixel (Freude eq. 4.11) and following the surface (eq. 4.12),
/// and the components' results are summed with their signs (eq. 5.10); the specular is added
/// after the blur.
struct SeparableSettings {
  /// The kernel K = sum_r sign_r (a_r horizontally, then a_r vertically), Freude eq. 5.10:
  /// 1..kMaxKernelComponents components (rank 1: one). An energy-conserving kernel has
  /// sum_r sign_r (sum of a_r's weights)^2 = 1 per channel. Objects of one frame may differ in rank.
  std::vector<SeparableComponent> components;
  /// Depth difference (mm, along the view ray) at which a tap is fully replaced by the centre
  /// colour (follow-surface, eq. 4.12: t = |i_d - o_d| / followSurfaceMm). 0: the largest
  /// |offset| of any component.
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

/// A rank-1 kernel: one component of `taps` ({w_R, w_G, w_B, offset_mm}) with sign +1.
inline SeparableSettings rankOneSeparable(std::vector<Float4> taps) {
  SeparableSettings s;
  s.components.push_back({std::move(taps), {1.0f, 1.0f, 1.0f}});
  return s;
}

/// Texture-space diffusion (d'Eon et al. 2007). Not in this build: branch `tsd`.
struct TextureSpaceSettings {};
/// Ray-marched subsurface texture mapping (François et al.). Not in this build: branch `raymarch`.
struct RayMarchSettings {};
/// Layered parallax mapping. Not in this build: branch `raymarch`.
struct ParallaxSettings {};

/// Per-object settings; the alternative chosen is the object's shading method.
using MethodSettings =
    std::variant<LitSettings, SeparableSettings, TextureSpaceSettings, RayMarchSettings, ParallaxSettings>;

/// The most taps a separable kernel component may have.
inline constexpr int kMaxKernelTaps = 64;
/// The most components (rank) a separable kernel may have; each costs two 1D passes.
inline constexpr int kMaxKernelComponents = 8;
/// The most transmittance rows of a separable material.
inline constexpr int kMaxTransmittanceRows = 16;

/// The method an object's settings select.
inline ShadingMethod shadingMethod(const MethodSettings& settings) {
  return static_cast<ShadingMethod>(settings.index());
}

/// A stable lower-case name ("lit", "separable", "texture-space", "ray-march", "parallax").
std::string_view shadingMethodName(ShadingMethod method);

}  // namespace tissue::render
