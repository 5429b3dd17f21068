#pragma once
/// \file
/// The shading methods: a closed set (STYLE.md rule 5), one enum and one variant of per-method
/// settings. An object's method is the variant's alternative; `shadingMethod()` names it, and
/// the pipeline switches on it once per object. Lengths are mm.

#include <cstdint>
#include <string_view>
#include <variant>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::render {

/// A texture uploaded to a renderer (Renderer::createTexture); 0 = none (a default is used).
/// Here rather than in scene.h because method settings name textures too.
struct TextureHandle {
  std::uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
};

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
/// One inner layer of the layered-parallax method (Oat 2006; Norberg 2010 §2.2).
struct ParallaxLayer {
  /// sRGB base colour of the layer (e.g. a vessel network); none: the object's default base.
  TextureHandle base;
  float depthMm = 1.0f;  ///< mm below the outer surface along -N (d of Norberg eq. 17)
  /// Unitless 0..1 opacity of this layer over the deeper ones (Norberg §2.2: intermediate layers
  /// may be partly transparent); the deepest layer is always opaque.
  float opacity = 1.0f;
};

/// The most inner layers of a parallax object.
inline constexpr int kMaxParallaxLayers = 3;

/// The lightmap of the layered-parallax method: the texture-space irradiance pass (d'Eon et al.
/// 2007 with the culled §3 and clipped §5 maps of Jimenez and Gutierrez 2008), box-filtered to a
/// reduced resolution and blurred by a Poisson disc in several passes (Norberg §2.2.2, §3.2).
struct ParallaxLightmapSettings {
  int size = 1024;            ///< texels of the irradiance pass (T_max), 16..2048
  bool cull = true;           ///< Jimenez §3: no irradiance where the surface faces away (> 105 deg)
  bool clip = true;           ///< Jimenez §5: only what lies inside the view frustum
  int reduction = 4;          ///< the blurred map has size / reduction texels a side (1, 2, 4 or 8)
  float blurRadiusMm = 4.0f;  ///< mm on the surface: the total Poisson-disc radius of all passes
  int blurPasses = 3;         ///< passes; each uses radius blurRadiusMm / sqrt(passes) (§3.2)
};

/// Layered parallax multi-texturing (Oat 2006, as in Norberg 2010 §2.2 and §3.2). The outer layer
/// is the object's baseColor and normalMap with an opacity; the inner layers are looked up at the
/// texture coordinate the transmission vector reaches at their depth (eq. 15-18), lit by the
/// blurred texture-space lightmap and blurred by the transmission distance; the outer and inner
/// colours are blended by opacity x N.V (eq. 19). Meshes need unique UVs (the lightmap is drawn
/// in UV space).
struct ParallaxSettings {
  /// Outer-layer opacity map (unitless 0..1 in the red channel: 1 hides the inner layers, as
  /// data/textures/<mesh>/opacity.png); none: the constant `opacity`.
  TextureHandle opacityMap;
  float opacity = 0.5f;  ///< unitless 0..1, the outer layer's opacity without an opacity map
  /// 1..kMaxParallaxLayers inner layers, shallowest first, with increasing depths.
  std::vector<ParallaxLayer> layers{ParallaxLayer{}};
  /// Relative refractive index n_inside / n_outside of the outer layer (unitless, >= 1). 1 gives
  /// Oat's transmission vector (eq. 15-16); above 1 the vector is refracted by Snell's law.
  float refractiveIndex = 1.4f;
  /// mm of inner-layer blur (Poisson-disc radius) per mm the view ray travels to the layer
  /// (Norberg §2.2.2: "the blurring of the base texture depends on the transmission distance").
  float innerBlurPerMm = 0.15f;
  /// mm: the transmission distance (s of eq. 17) is clamped here, so grazing views (where
  /// |T_z| -> 0) cannot shift the lookup arbitrarily far.
  float maxTransmissionMm = 20.0f;
  ParallaxLightmapSettings lightmap;
};

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
