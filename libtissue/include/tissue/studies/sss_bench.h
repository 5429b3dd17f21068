#pragma once
/// \file
/// The SSS bench: subsurface-scattering methods on one frame of an organ, each setting timed and
/// measured against the CPU reference (tissue::reference::convolveScreen with the material's
/// dipole profile). Each method contributes rows through an SssBenchMethod entry (kSssBenchMethods).
/// GL: the renderer's context must be current for every call.

#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/materials.h"
#include "tissue/reference/screen_convolution.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// One measured setting.
struct SssBenchRow {
  std::string method;        ///< "separable", "texture-space", ...
  std::string setting;       ///< e.g. "preintegrated-17"
  double ms = 0.0;           ///< ms, median wall time of a whole frame (renderImage, read back)
  double methodMs = 0.0;     ///< ms, median CPU time of the method's own passes
  double imageRms = 0.0;     ///< RMS vs the reference, linear radiance (exposure 1)
  double relativeRms = 0.0;  ///< imageRms / mean reference radiance
};

/// A setting a method could not build for the material, and why.
struct SssBenchSkip {
  std::string method, setting, reason;
};

/// What every method's rows share: the renderer with the organ uploaded, the frame's scene (one
/// object; a method sets its settings), the optical material and the CPU reference.
struct SssBenchContext {
  render::Renderer* renderer = nullptr;
  render::Scene scene;
  int width = 320, height = 240;  ///< pixels
  int frames = 5;                 ///< timed frames per setting
  optics::ScatteringMaterial material;
  std::vector<reference::RadialProfile> profiles;  ///< by object id: [0] none, [1] the organ's truth
  std::vector<Float4> diffuse, position;           ///< the pre-blur frame the reference convolves
  std::vector<Float3> reference;                   ///< the reference result, per pixel
};

/// Uploads `organ` (its own UVs; smooth normals and UV tangent frames, studies::tsdOrganOf) as
/// the one object of ctx.scene with its base colour and normal map, a shadowed key light framed
/// on it, and its material's first layer with the pre-integrated dipole profile as the truth.
Result<void> setUpSssBench(SssBenchContext& ctx, const scene::OrganAssets& organ);

/// Renders `ctx.scene` `ctx.frames` times (after one warm-up); median frame ms and the median
/// summed CPU ms of the passes whose names start with `passPrefix`.
Result<std::pair<double, double>> timeFrames(SssBenchContext& ctx, const std::string& passPrefix);

/// Fills ctx.diffuse/position from the last frame (Diffuse and Position views; with MSAA every
/// covered pixel, silhouettes included, holds a real surface sample) and convolves the reference, once.
Result<void> ensureReference(SssBenchContext& ctx);

/// Compares the last frame's blurred diffuse (FrameView::BlurredDiffuse, its coverage weight
/// removed) with the reference.
Result<reference::ImageError> compareLastFrame(SssBenchContext& ctx);

/// The separable method's rows: every kernel model at 7, 11, 17 and 25 taps, then rank-R kernels
/// (SVD rank 2 and 3, "svd2-17"; d'Eon 2 and 4 Gaussians, "deon4-17") at 11 and 17. Models that cannot
/// be built for the material (e.g. manual without Table A.1 parameters) go to `skipped`.
Result<std::vector<SssBenchRow>> separableBenchRows(SssBenchContext& ctx, std::vector<SssBenchSkip>& skipped);

/// The texture-space method's rows: 2, 4 and 6 Gaussians fitted to the material's dipole
/// profile, all three irradiance-map optimisations on, T_max = 1024, pre-scatter albedo (the
/// quantity the separable method blurs), compared with the same reference.
Result<std::vector<SssBenchRow>> textureSpaceBenchRows(SssBenchContext& ctx,
                                                       std::vector<SssBenchSkip>& skipped);

/// The image error of a frame's blurred diffuse against the exact convolution of its pre-blur one.
struct ReferenceError {
  double referenceMs = 0.0;  ///< ms, the CPU convolution's wall time
  double imageRms = 0.0;     ///< RMS, linear radiance
  double relativeRms = 0.0;  ///< imageRms / mean reference radiance
};

/// The renderer's last frame (its BlurredDiffuse, read back as it is) against the exact
/// screen-space convolution (reference::convolveScreen with `truth` for object 1) of the pre-blur
/// `diffuse` and `position` of the same frame, MSAA silhouettes dropped (dropPartialCoverage):
/// the demo's measure of a method it switched to at run time.
Result<ReferenceError> lastFrameReferenceError(render::Renderer& renderer, const render::FloatImage& diffuse,
                                               const render::FloatImage& position,
                                               const reference::RadialProfile& truth);

/// A method of the bench: its name and how it makes its rows.
struct SssBenchMethod {
  const char* name;
  Result<std::vector<SssBenchRow>> (*rows)(SssBenchContext& ctx, std::vector<SssBenchSkip>& skipped);
};

/// The bench's methods, in the order of its results.
inline constexpr SssBenchMethod kSssBenchMethods[] = {
    {"separable", separableBenchRows},
    {"texture-space", textureSpaceBenchRows},
};

/// What `tissue-sim sss-bench` asks of the bench.
struct SssBenchConfig {
  int width = 320, height = 240;  ///< pixels
  int frames = 5;                 ///< timed frames per setting (median)
  int samples = 0;                ///< the caller's renderer's MSAA samples (for the report)
  std::string glRenderer;         ///< GL_RENDERER of the caller's context (for the report)
};

/// The bench's rows, its skips and its report: sss_bench.json (the JSON: mesh, material, width,
/// height, frames, samples, gl_renderer, reference, results [method, setting, ms, method_ms,
/// image_rms, relative_rms], skipped [method, setting, reason]), sss_bench.md and sss_bench.csv
/// (one table row per measured setting).
struct SssBenchResult {
  std::vector<SssBenchRow> rows;
  std::vector<SssBenchSkip> skipped;
  StudyOutput output;
};

/// Loads `source` (its own UVs; no atlas), sets the bench up on `renderer` (its context current)
/// and runs every method of kSssBenchMethods. Errors name the mesh or the method.
Result<SssBenchResult> runSssBench(render::Renderer& renderer, const scene::OrganSource& source,
                                   const SssBenchConfig& config);

}  // namespace tissue::studies
