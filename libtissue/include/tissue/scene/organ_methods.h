#pragma once
/// \file
/// Every shading method's settings for one organ, derived from its material file (the one
/// reader, material_file.h) and its uploaded textures: written once, for tissue-sim, the viewer,
/// the C API and any host.
///   lit            Blinn-Phong with the optical base colour (uploadOrganTextures) and normal map
///   separable      Jimenez et al. 2015 separable SSS: a kernel of the first layer's dipole
///                  profile (model and taps from MethodChoices; Freude eq. 5.10, 5.17-5.18)
///   texture-space  d'Eon et al. 2007 with the culled, depth-sized and clipped maps of Jimenez et
///                  al. 2008: Gaussians fitted to the same profile (d'Eon eq. 4.15)
///   ray-march      François et al. 2006: the whole layer stack and its subsurface map, with
///                  each layer's multiple scattering, Fresnel and the surface specular (§3)
///   parallax       Oat 2006 (Norberg 2010 §2.2): the inner layer (inner_base) under the
///                  outer one's opacity

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/reference/screen_convolution.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/render/shading.h"
#include "tissue/scene/organ_assets.h"

namespace tissue::scene {

/// The choices behind the methods' settings (plain struct with defaults: the main job's).
struct MethodChoices {
  /// Lit: the wrap term (render::LitSettings::wrap, unitless 0..1; 0: plain Lambert).
  float litWrap = 0.0f;
  /// Lit: the wrap term from the optics instead (opticalWrap): the quality controller's fallback
  /// and the atlas's "lit wrap" row.
  bool litWrapFromOptics = false;
  std::string kernel =
      "preintegrated";           ///< separable model: svd, preintegrated, guided, manual, deon, jimenez
  int taps = 17;                 ///< separable taps, odd, 5..63
  int rank = 1;                  ///< separable components (svd, deon)
  int gaussians = 6;             ///< texture-space Gaussians, 1..8
  int mapSize = 1024;            ///< texture-space T_max, irradiance map texels
  bool cull = true;              ///< texture-space and parallax lightmap: Jimenez et al. 2008 §3
  bool clip = true;              ///< texture-space and parallax lightmap: Jimenez et al. 2008 §5
  bool depthSize = true;         ///< texture-space: map size from the distance (Jimenez §4)
  int samples = 32;              ///< ray-march samples per pixel, 1..256
  bool adaptive = true;          ///< ray march: adaptive quality (RayMarchSettings::adaptive)
  float parallaxDepthMm = 1.5f;  ///< mm, depth of the parallax inner layer below the surface
  /// Parallax: n_inside / n_outside of the outer layer (>= 1); empty: the material file's ior.
  std::optional<float> refractiveIndex{};
  /// Parallax lightmap: size, reduction, blur (its cull and clip are the fields above).
  render::ParallaxLightmapSettings lightmap{};
};

/// An organ's textures on one renderer (empty handles: not there).
struct OrganTextures {
  render::TextureHandle baseColor, normalMap, opacity, innerBase, subsurfaceMap;
};

/// Uploads the organ's textures (the subsurface map as linear data). The colour comes from the
/// material's optics (material_file.h): the base colour is opticalBaseColor (the painted
/// base_color at most a luminance detail, MaterialFile::baseColorDetail), and with a subsurface
/// map the parallax inner layer is opticalLayerImage at the default parallax depth
/// (MethodChoices{}.parallaxDepthMm). The renderer's context must be current.
Result<OrganTextures> uploadOrganTextures(render::Renderer& renderer, const OrganAssets& organ);
/// Frees them (context current).
void destroyOrganTextures(render::Renderer& renderer, OrganTextures& textures);

/// The methods `organ` can be shaded with, lit first: separable always; texture-space when its
/// UVs are unique; ray-march with a subsurface map; parallax with an inner layer.
std::vector<render::ShadingMethod> offeredMethods(const OrganAssets& organ);

/// `method`'s settings for `organ`. Errors when the organ lacks what the method needs (naming
/// the material file and what to add) or a kernel cannot be built.
Result<render::MethodSettings> organMethod(render::ShadingMethod method, const OrganAssets& organ,
                                           const OrganTextures& textures, const MethodChoices& choices = {});

/// The separable method's ground truth for `organ`: its first layer's dipole profile normalised
/// to 1 (mm^-2), the R a CPU reference convolves with (reference::convolveScreen), built as the
/// kernel of `choices` is (materials::makeSeparableMaterial).
Result<reference::RadialProfile> separableTruth(const OrganAssets& organ, const MethodChoices& choices = {});

/// The wrap term (render::LitSettings::wrap, unitless) that stands for the organ's light
/// diffusing past the terminator: scattering carries light about a diffusion length
/// ell = 1 / sigma_tr (the first layer's smallest, i.e. the band that travels furthest) around a
/// surface whose curvature radius is about R = sqrt(area / 4 pi) (a sphere of the organ's area),
/// so light reaches ell / R radians past the terminator, N.L >= -ell / R, the zero of Green
/// 2004's (N.L + w) / (1 + w). Clamped to 0..0.5. The liver: ell 1.8 mm, R ~ 50 mm, w ~ 0.04.
float opticalWrap(const OrganAssets& organ);

/// The organ's outer surface for the renderer: its specular reflectance at normal incidence is
/// the Fresnel F0 of the material's ior (specularF0), as the truth's boundary reflects
/// (common/specular.glsl); `ambient` (linear RGB radiance) is an artist's fill light that the
/// truth does not have (SceneSettings::ambient).
render::Material surfaceMaterialOf(const OrganAssets& organ, Float3 ambient = render::Material{}.ambient);

/// The organ as a scene object of `mesh`, with its textures, `method` and `surface`
/// (surfaceMaterialOf).
render::SceneObject organObject(render::MeshHandle mesh, const OrganTextures& textures,
                                render::MethodSettings method, const render::Material& surface);

/// "lit", "separable", "texture-space", "ray-march" (or "raymarch") or "parallax"; the error
/// lists them.
Result<render::ShadingMethod> parseShadingMethod(std::string_view name);

}  // namespace tissue::scene
