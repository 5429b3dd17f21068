#pragma once
/// \file
/// The speed-accuracy atlas (issue 13): every shading method and setting of the renderer on
/// several frames of one organ, each scored against the path-traced truth of the same frame
/// (scene::renderTruth: the renderer's camera, lights and the organ's current shape). Scores over
/// the organ's pixels (those the truth's centre ray meets): the relative RMS of linear radiance
/// and the PSNR (dB) of the tone-mapped image (exposure, Reinhard x / (1 + x), sRGB: the renderer's
/// output transform), with a per-pixel error image. The truth of each frame is cached on disk
/// under a hash of everything it depends on (mesh positions, material, camera, lights, settings).
/// GL: runAtlas needs the renderer's context current; the metrics are GL-free.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/scene.h"
#include "tissue/studies/report.h"
#include "tissue/truth/path_tracer.h"

namespace tissue::studies {

/// A method image's scores against the truth.
struct AtlasScore {
  double relRms = 0.0;  ///< sqrt(sum |M - T|^2 / sum |T|^2) over organ pixels and RGB, linear radiance
  double psnrDb = 0.0;  ///< 10 log10(1 / MSE) of the tone-mapped images (0..1), organ pixels and RGB
  int pixels = 0;       ///< organ pixels scored
  /// The least-squares gain k = sum M.T / sum T.T: the method's overall level against the truth's.
  double gain = 0.0;
  /// The relative RMS of M / k against T: the error left once the level is matched (the shape).
  double shapeRelRms = 0.0;
};

/// Scores `method` (linear RGB radiance per pixel, rows top to bottom, the truth's size) against
/// `truth` over the pixels with mask != 0. Empty mask or sizes that differ: relRms NaN.
AtlasScore scoreAgainstTruth(std::span<const Float3> truth, std::span<const Float3> method,
                             std::span<const std::uint8_t> mask, float exposure = 1.0f);

/// The truth's own noise on the same measure: sqrt(sum stderr^2 / sum |T|^2) over the mask.
double truthNoiseRelRms(const truth::TruthImage& truth);

/// The error once the truth's noise is taken out: sqrt(max(0, err^2 - noise^2)).
double debiasedError(double relRms, double noiseRelRms);

/// Two renderings A and B scored against one noisy truth T^ = T + n: which is closer, and can the
/// truth tell? The difference of their squared relative errors,
///   E_A^2 - E_B^2 = sum (|A - T^|^2 - |B - T^|^2) / sum |T^|^2,
/// is unbiased by the noise (each squared error carries the same sum of n^2, which cancels), but
/// carries its cross term -2 sum n (A - B) / sum |T^|^2, whose standard error is
///   2 sqrt(sum sigma^2 |A - B|^2) / sum |T^|^2
/// with sigma the truth's per-pixel standard error (per band). A difference is resolved when it is
/// over `sigmas` of these. Over the pixels with mask != 0; sizes that differ: NaN.
struct ErrorDifference {
  double squared = 0.0;        ///< E_A^2 - E_B^2 (unitless, squared relative RMS)
  double squaredStderr = 0.0;  ///< its standard error from the truth's noise
  /// A is lower than B by more than `sigmas` standard errors.
  bool aLower(double sigmas = 2.0) const { return squared < -sigmas * squaredStderr; }
  /// B is lower than A by more than `sigmas` standard errors.
  bool bLower(double sigmas = 2.0) const { return squared > sigmas * squaredStderr; }
};
ErrorDifference errorDifference(std::span<const Float3> truth, std::span<const Float3> truthStderr,
                                std::span<const Float3> a, std::span<const Float3> b,
                                std::span<const std::uint8_t> mask);

/// The renderer's output transform of linear radiance (exposure, Reinhard, sRGB), 0..1.
Float3 toneMap(Float3 radiance, float exposure = 1.0f);

/// An image of linear radiance (rows top to bottom) through toneMap, as displayed. RGBA8.
Image8 toneMapped(std::span<const Float3> linear, int width, int height, float exposure = 1.0f);

/// A per-pixel error image: |M - T| (luminance) over the mean truth luminance, mapped 0..`scale`
/// to black-red-yellow-white; pixels off the mask dark blue. RGBA8.
Image8 errorImage(std::span<const Float3> truth, std::span<const Float3> method,
                  std::span<const std::uint8_t> mask, int width, int height, double scale = 0.5);

/// The indices of the Pareto-optimal points (no other point has both smaller or equal cost and
/// smaller or equal error, one of them strictly), by increasing cost.
std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error);

/// One method setting the atlas scores: the method, its name in the rows, the choices behind it.
struct AtlasSetting {
  render::ShadingMethod method = render::ShadingMethod::Lit;
  std::string name;  ///< the rows' setting ("default", "wrap", "preintegrated-17", "6g-opt", "50", ...)
  scene::MethodChoices choices;
};

/// Every setting the atlas scores (quick: fewer): lit plain and with the quality controller's
/// wrap term ("wrap": scene::opticalWrap), separable kernels and taps, texture-space Gaussians
/// with and without Jimenez's optimisations, ray-march samples (fixed and adaptive), parallax.
/// Each name reads back through scene::choicesOfSetting.
std::vector<AtlasSetting> atlasSettings(bool quick);

/// One scored render.
struct AtlasRow {
  std::string method;   ///< lit, separable, texture-space, ray-march, parallax
  std::string setting;  ///< e.g. "preintegrated-17", "6g-opt", "50", "adaptive"
  std::string frame;    ///< rest, poked, close-up, oblique, low, far, grazing, backlit
  double ms = 0.0;      ///< ms, median whole-frame time (renderImage, read back)
  double relRms = 0.0;
  double psnrDb = 0.0;
  double gain = 0.0;         ///< AtlasScore::gain
  double shapeRelRms = 0.0;  ///< AtlasScore::shapeRelRms
  /// Against the frame's lowest-error row, on the same truth (errorDifference): relRms^2 minus
  /// its, and the standard error of that from the truth's noise. Paired, the comparison resolves
  /// differences far below the truth's noise (its n^2 cancels; only the cross term with the two
  /// images' difference is left).
  double squaredVsBest = 0.0, squaredVsBestStderr = 0.0;
  /// Worse than the frame's best by more than two of those standard errors (false: a tie the truth
  /// cannot split, or the best itself).
  bool worseThanBest = false;
};

/// One frame's truth.
struct AtlasTruth {
  std::string frame;
  int samplesPerPixel = 0;
  double ms = 0.0;        ///< ms to trace it (0 when read from the cache; see cachedMs)
  double cachedMs = 0.0;  ///< ms the cached image took when it was traced
  double noiseRelRms = 0.0;
  bool fromCache = false;
  int organPixels = 0;
  /// degrees between the view ray to the organ's centre and its surface normal (scene::organView)
  double viewAngleDeg = 0.0;
};

/// What `tissue-sim atlas` asks.
struct AtlasConfig {
  scene::OrganDesc organ;          ///< its scenario (the poke) and material file
  scene::SceneSettings scene;      ///< the material rule and folders (scene::loadSimulatedOrgan)
  std::filesystem::path cacheDir;  ///< truth images; empty: no cache
  bool quick = false;              ///< small images, fewer settings, fewer samples
  int width = 160, height = 120;   ///< pixels (quick: 96 x 72)
  int frames = 3;                  ///< timed frames per setting (median)
  int truthSpp = 256;              ///< samples per pixel at most (quick: 64)
  double truthSeconds =
      120.0;  ///< s per frame at most for the truth (quick: 5; close-up 6x, oblique and low 4x, backlit 3x)
  int threads = 0;  ///< truth threads; 0: all cores
  /// Score with the product's artist's terms, which the truth does not have: the ambient fill
  /// light and the normal maps of SceneSettings (`scene`). Off (the default), the scored frames
  /// have neither, as the truth; on, the report measures what they cost.
  bool artistTerms = false;
  std::string glRenderer;  ///< GL_RENDERER, for the report
  /// One line of progress (each truth pass, each frame's methods), on the calling thread; empty:
  /// none. The library never writes to stderr itself.
  std::function<void(const std::string&)> onProgress;
};

/// The atlas: rows, truths and the report (atlas.json, atlas.md, atlas.csv, atlas.png: ms against
/// rel RMS, log-log, one colour per method and the Pareto front; per frame the truth's tone-mapped
/// image and each method's best setting's error image).
struct AtlasResult {
  std::vector<AtlasTruth> truths;
  std::vector<AtlasRow> rows;
  StudyOutput output;
};

/// Runs the atlas on `renderer` (its context current; MSAA off). Errors name the file or step.
Result<AtlasResult> runAtlas(render::Renderer& renderer, const AtlasConfig& config);

}  // namespace tissue::studies
