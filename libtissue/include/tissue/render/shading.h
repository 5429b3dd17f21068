#pragma once
/// \file
/// The shading methods: a closed set (STYLE.md rule 5), one enum and one variant of per-method
/// settings. An object's method is the variant's alternative; `shadingMethod()` names it, and
/// the pipeline switches on it once per object. Lengths are mm.

#include <string_view>
#include <variant>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/texture_space_math.h"

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

/// Texture-space diffusion (d'Eon et al. 2007) with the irradiance-map optimisations of Jimenez
/// and Gutierrez 2008: the object's irradiance (every light, shadows, transmission, lit as the
/// separable method lights its diffuse) is rendered into its UV space, blurred by one separable
/// Gaussian per profile term with a per-frame stretch correction, summed with the profile's
/// weights and drawn by the camera into the diffuse target (the separable blur leaves it as it
/// is). The mesh needs unique UVs (mesh::computeUvAtlas makes them).
struct TextureSpaceSettings {
  /// The diffusion profile R(r) = sum_i w_i G(v_i, r): variances v_i (mm^2, increasing) and RGB
  /// weights w_i (unitless; each channel sums to 1 for an energy-conserving profile), 1 to
  /// kMaxTsdGaussians terms (e.g. optics::fitGaussians of the material's profile).
  std::vector<ProfileGaussian> gaussians;
  bool cull = true;       ///< Jimenez §3: no irradiance nor convolution beyond 105 degrees from the eye
  bool clip = true;       ///< Jimenez §5: clip the irradiance pass to the view frustum (eq. 5-6)
  bool depthSize = true;  ///< Jimenez §4: map size T = s T_max from the distance (eq. 3-4)
  float clipD = 1.0f;     ///< D of eq. 5 (1: the exact frustum; more keeps an off-screen margin)
  /// d_ref of eq. 3, mm: the distance at which the whole map is used. 0: where one texel of the
  /// full map covers one pixel, d_ref = H / (2 tan(fov / 2) texelsPerMm).
  float referenceDistanceMm = 0.0f;
  /// The UV map's density at T_max, texels per mm, for d_ref; 0: measured from the mesh at
  /// upload, sqrt(UV area / surface area) * mapSize.
  float texelsPerMm = 0.0f;
  int mapSize = 1024;    ///< T_max, texels (maps are allocated once per size, shared by objects)
  int blurHalfTaps = 3;  ///< 2 h + 1 taps per 1D Gaussian pass (d'Eon: 7), 1..8
  /// Texturing: the map holds albedo^p x irradiance and the camera pass multiplies by
  /// albedo^(1 - p). 1: pre-scatter, as the separable method (so both diffuse the same
  /// quantity); 0: post-scatter; 0.5: d'Eon et al.'s mix.
  float albedoPreScatter = 1.0f;
  /// Transmittance through thin parts, as SeparableSettings::transmittance: {T_R, T_G, T_B,
  /// thickness_mm} rows, added to the irradiance before the diffusion; empty = none.
  std::vector<Float4> transmittance;
  float transmissionShrinkMm = 0.5f;  ///< mm, as SeparableSettings::transmissionShrinkMm
};
/// Ray-marched subsurface texture mapping (François et al.). Not in this build: branch `raymarch`.
struct RayMarchSettings {};
/// Layered parallax mapping. Not in this build: branch `raymarch`.
struct ParallaxSettings {};

/// Per-object settings; the alternative chosen is the object's shading method.
using MethodSettings =
    std::variant<LitSettings, SeparableSettings, TextureSpaceSettings, RayMarchSettings, ParallaxSettings>;

/// The most taps a separable kernel may have.
inline constexpr int kMaxKernelTaps = 64;
/// The most transmittance rows of a separable or texture-space material.
inline constexpr int kMaxTransmittanceRows = 16;
/// The most Gaussians of a texture-space profile.
inline constexpr int kMaxTsdGaussians = 8;

/// The method an object's settings select.
inline ShadingMethod shadingMethod(const MethodSettings& settings) {
  return static_cast<ShadingMethod>(settings.index());
}

/// A stable lower-case name ("lit", "separable", "texture-space", "ray-march", "parallax").
std::string_view shadingMethodName(ShadingMethod method);

}  // namespace tissue::render
