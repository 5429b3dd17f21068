#pragma once
/// \file
/// An organ ready for layered parallax (Oat 2006; Norberg 2010 §2.2), shared by the parallax
/// render and parallax-study: unique UVs (its own, else the scene module's automatic atlas), the
/// layer textures its material file names (base colour, normal map, opacity, the inner layer's
/// vessel network; scene::loadOrganAssets, dropped with the atlas since they belong to the file's
/// UVs), and a render::Scene of one parallax object on the caller's renderer. Lengths in mm.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/studies/parallax_study.h"
#include "tissue/studies/report.h"
#include "tissue/studies/texture_space_organ.h"

namespace tissue::studies {

/// The parallax settings a command may change (defaults: ParallaxSettings').
struct ParallaxOptions {
  float layerDepthMm = 1.5f;  ///< mm, the one inner layer's depth
  render::ParallaxSettings settings;
};

/// The organ and its layer textures.
struct ParallaxOrgan {
  TsdOrgan organ;
  std::optional<Image8> baseColor, normalMap, opacity, innerBase;  ///< sRGB / tangent space / red
  /// The mesh's own UVs and its material's inner layer (false: atlas or no inner_base; the
  /// object then draws with the renderer's default colours).
  bool textured = false;
};

/// Loads `source` (scene::loadOrganAssets with the UV-atlas fallback; an empty material: the
/// default organ, untextured). Errors name the file at fault.
Result<ParallaxOrgan> loadParallaxOrgan(const scene::OrganSource& source);

/// Uploads `organ` to `renderer` (its context current) as the one parallax object of the returned
/// scene (one inner layer at options.layerDepthMm; its textures when textured), the camera
/// framing the mesh for width / height = `aspect`, no lights.
Result<render::Scene> makeParallaxScene(render::Renderer& renderer, const ParallaxOrgan& organ,
                                        const ParallaxOptions& options, float aspect);

/// What `tissue-sim parallax-study` asks of the study.
struct ParallaxStudyRun {
  ParallaxStudyConfig study;                ///< depths, indices, view angles, sample points
  int imageWidth = 384, imageHeight = 288;  ///< pixels, the patch images
  std::string imageFolder;                  ///< where the caller writes the images, for the JSON's list
};

/// The study's rows and report: parallax_study.json (results [surface, what, depth_mm,
/// refractive_index, angles [samples, reached, miss_fraction, mean_error_mm, p95_error_mm,
/// max_error_mm, mean_parallax_offset_mm, mean_true_offset_mm, view_angle_deg]], images,
/// max_transmission_mm), parallax_study.md, parallax_study.csv (one row per surface, depth, index
/// and angle), and the patch seen at 0, 45, 75 and 85 degrees (parallax_patch_<angle>deg.png).
struct ParallaxStudyResult {
  std::vector<ParallaxRow> rows;
  StudyOutput output;
};

/// The lookup study (studyParallax) on a plane (the control), a 40 mm sphere and the organs of
/// `organSource("liver")` and `organSource("tube")`, and images of the patch of
/// `organSource("patch")` (its material file when there is one; inner layer 3 mm deep, opacity
/// 0.3, a directional light) rendered on `renderer` (its context current): the inner vessels'
/// shift and, at grazing angles, the eq. 19 fade to the outer layer. Errors name the mesh.
Result<ParallaxStudyResult> runParallaxStudy(
    render::Renderer& renderer, const std::function<scene::OrganSource(const std::string&)>& organSource,
    const ParallaxStudyRun& run = {});

}  // namespace tissue::studies
