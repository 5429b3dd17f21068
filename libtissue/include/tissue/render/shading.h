#pragma once
/// \file
/// The shading methods: a closed set (STYLE.md rule 5), one enum and one variant of per-method
/// settings. An object's method is the variant's alternative; `shadingMethod()` names it, and
/// the pipeline switches on it once per object. Lengths are mm.

#include <cstdint>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/render/handles.h"
#include "tissue/render/texture_space_math.h"

namespace tissue::render {

/// How an object is shaded. The order matches MethodSettings' alternatives.
enum class ShadingMethod { Lit, Separable, TextureSpace, RayMarch, Parallax };

/// Blinn-Phong through the normal map, straight into the HDR target. No subsurface scattering.
struct LitSettings {
  /// Wrap lighting, unitless 0..1: the diffuse term max(0, (N.L + wrap) / (1 + wrap)) instead of
  /// max(0, N.L) (Green 2004, GPU Gems ch. 16: the cheapest stand-in for light scattered past the
  /// terminator; Unreal Substrate's Wrap tier for distant subsurface objects). 0: plain Lambert.
  float wrap = 0.0f;
};

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
/// One layer of a ray-marched material (François et al. 2006, Table 1).
struct RayMarchLayer {
  Float3 sigma_s{1.0f, 1.0f, 2.0f};  ///< scattering coefficient per RGB channel, mm^-1
  Float3 sigma_t{1.5f, 1.5f, 2.5f};  ///< extinction coefficient per RGB channel, mm^-1 (>= sigma_s)
  float schlickK = 0.0f;             ///< Schlick phase parameter, unitless (-1, 1) (optics::schlickKFromG(g))
  /// Multiple-scattered reflectance of the layer as a half-space per RGB channel, unitless 0..1
  /// (optics::semiInfiniteReflectance(...).multiple); zero everywhere: no multiple scattering.
  Float3 multipleAlbedo{0.0f, 0.0f, 0.0f};
  /// Effective transport coefficient sqrt(3 sigma_a sigma_t') per RGB channel, mm^-1: how deep
  /// the diffuse light reaches, which weights the layers' multipleAlbedo per pixel.
  Float3 sigmaTr{0.0f, 0.0f, 0.0f};
};

/// Ray-marched subsurface texture mapping (François et al. 2006, Algorithms 1-2; Norberg 2010
/// §2.1, §3.1): single scattering through a layer stack whose boundary depths come from RGBA
/// subsurface maps, the light's entry found through the mesh's per-vertex fitted planes
/// interpolated across each triangle (eq. 9-10, 14-15), straight into the HDR radiance target.
/// The object's mesh must carry planes (MeshArrays::planes, updated every frame through
/// MeshUpdate::planes). Point and directional lights; no shadow maps (the march itself is the
/// light transport). Lengths mm, coefficients mm^-1.
struct RayMarchSettings {
  // The material.
  /// 4N + 1 layers, top first, for N subsurface maps (layer i ends at boundary i; the last is unbounded).
  std::vector<RayMarchLayer> layers;
  /// N = 1 or 2 RGBA maps of boundary depths (4 per map, 0..1 of depthScaleMm), uploaded with
  /// TextureEncoding::LinearData (values as stored, bilinear, no mip-maps, clamped).
  std::vector<TextureHandle> subsurfaceMaps;
  float depthScaleMm = 3.0f;     ///< mm, the depth a map value of 1 stands for
  float uvPerMm = 1.0f / 80.0f;  ///< texture units per mm along T and B (subsurface::uvPerMmOf)
  // The march (subsurface::MarchSettings).
  int samples = 50;                    ///< fixed sample count along P..M_max, 1..256
  float depthMaxMm = 3.0f;             ///< Depth_max of eq. 15, mm along N_S
  float attenuationThreshold = 1e-3f;  ///< stop once exp(-tau_PM) falls below it, unitless (0: never)
  float minCosView = 0.1f;             ///< lower clamp of N_S . omega_out in eq. 15 (grazing views)
  bool jitter = true;                  ///< noisy sampling from a per-pixel hash (Norberg §3.1.2)
  unsigned seed = 0;                   ///< frame seed of the hash
  // Adaptive quality (subsurface::AdaptiveSettings): the count per pixel from view angle, layer
  // depth and screen footprint.
  bool adaptive = false;            ///< on: samples is ignored
  int minSamples = 4;               ///< adaptive floor
  int maxSamples = 100;             ///< adaptive ceiling
  float depthResolutionMm = 0.06f;  ///< adaptive: wanted depth step, mm
  float cutoff = 0.03f;             ///< adaptive: round-trip transmittance where the march stops, 0..1
  float texelsPerStep = 1.5f;       ///< adaptive: wanted sideways step, texels or pixels
  /// Unitless factor on the single-scattered radiance written to the HDR target (single
  /// scattering alone is dim: it carries a few percent of the light). The scene's light
  /// radiance is E / pi (the lit method's Lambert convention, L = albedo radiance cos), so pi
  /// makes the march see the irradiance E: the physically composed material
  /// (scene::organMethod) uses pi.
  float radianceScale = 8.0f;
  // The surface (François et al. 2006 §3: specular and diffuse reflection added to the single
  // scattering; Norberg 2010 §2.2.2). All off by default: the march alone, as the CPU model.
  /// Relative index of refraction of the tissue, >= 1. Above 1 the light entering and leaving
  /// is weighted by the Fresnel transmittance (1 - F), Schlick's approximation with
  /// F0 = ((n - 1) / (n + 1))^2, and the Fresnel-weighted Blinn-Phong specular of the outer
  /// surface (the object's Material::shininess) is added. 1: no boundary.
  float ior = 1.0f;
  /// The outer surface's specular lobe on or off (only with ior > 1).
  bool specular = false;
  /// Debug view: write samples marched / 100 as grey radiance (alpha 1) instead of the radiance.
  bool showSamples = false;
};
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

/// The most taps a separable kernel component may have.
inline constexpr int kMaxKernelTaps = 64;
/// The most components (rank) a separable kernel may have; each costs two 1D passes.
inline constexpr int kMaxKernelComponents = 8;
/// The most subsurface maps of a ray-marched material (4 boundaries each; 4N + 1 layers).
inline constexpr int kMaxSubsurfaceMaps = 2;
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
