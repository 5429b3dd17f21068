#pragma once
/// \file
/// The budget bench (issue 16): a scene of several organs seen through a laparoscope with its
/// light beside the lens (the poked organ in close-up, about 100 mm away, two at mid distance, two
/// far and small), the close-up deformed by a replayed session, rendered under frame budgets from
/// tight to loose with the quality controller choosing each organ's method and setting
/// (Scene::setBudgetMs), and with every single table setting applied to all organs. Each run's
/// frame times (upload, render, read back: what a host's frame pays for the tissue) and the error
/// of its last frame against the path-traced truth of the same frame (the organs' transformed
/// meshes concatenated into one TruthMesh with the organs' one material; studies/atlas.h's
/// scores). GL: the scene's own headless context.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/scene/scene.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// What `tissue-sim budget-bench` asks (plain struct with defaults).
struct BudgetBenchConfig {
  scene::SceneSettings scene;             ///< data folders, shaders, the controller's settings
  std::filesystem::path mesh;             ///< the organs' mesh (data/meshes/liver.obj)
  std::filesystem::path material;         ///< their material (data/materials/liver.json)
  std::filesystem::path session;          ///< the replayed session (data/sessions/liver_poke_grasp.json)
  int firstFrame = 140, lastFrame = 200;  ///< the session's frames played (the poke's descent)
  int width = 128, height = 96;           ///< pixels, of the renders and the truth
  std::vector<double> budgetsMs;          ///< empty: three from the fixed settings' measured times
  int warmupFrames = 40;                  ///< per run, untimed (the controller learns)
  int timedFrames = 60;                   ///< per run
  /// ms: a fixed setting whose frame takes longer is dropped after that frame (it fits no budget
  /// here: texture space without culling draws five 1024^2 maps, about 0.5 s a frame on llvmpipe).
  double maxFixedFrameMs = 400.0;
  double truthSeconds = 120.0;  ///< s for the truth at most
  int truthSpp = 4096;          ///< truth samples per pixel at most
  int threads = 0;              ///< truth threads; 0: all cores
  /// A folder of truth images named by a hash of everything the truth depends on (the meshes'
  /// positions, material, camera, lights, tracer settings and time): read when there, else
  /// written. Empty: none.
  std::filesystem::path truthCacheDir;
  /// Score with the product's artist's terms, which the truth does not have: the ambient fill
  /// light and the normal maps of SceneSettings (`scene`). Off (the default), the scored frames
  /// have neither, as the truth; on, the report measures what they cost.
  bool artistTerms = false;
  std::function<void(const std::string&)> onProgress;  ///< one line per step; empty: none
};

/// What the controller believed one table option costs at the end of a budget run: the cost it
/// plans with (QualityController::planningCosts, learned or calibrated from the prior) on each
/// organ's footprint, and its method's passes of no object.
struct LearnedOptionCost {
  std::string method, setting;
  int samples = 0;              ///< steady samples learned for the option itself
  std::vector<double> organMs;  ///< ms, per organ (placements' order) at its last footprint
  /// per organ: the error the controller expects of the option there (its table error moved along
  /// the organ's view angle and footprint, without the confidence charge)
  std::vector<double> organExpectedRelRms;
  double passMs = 0.0;  ///< ms, its method's passes of no object, once a frame
};

/// One run: a budget with the controller, or a fixed setting.
struct BudgetRun {
  double budgetMs = 0.0;                         ///< 0 for a fixed setting
  std::string method, setting;                   ///< the fixed setting (empty for the controller)
  double frameMsMedian = 0.0, frameMsP95 = 0.0;  ///< ms
  double relRms = 0.0, relRmsDebiased = 0.0;     ///< the last frame against the truth
  std::vector<scene::BudgetChoice> choices;      ///< the controller's, at the last frame
  int planChanges = 0;                           ///< the controller's plans during the run
  int switchesDeferred = 0;     ///< gains the controller left because their switch frame would not fit
  double plannedForMs = 0.0;    ///< ms, the budget the last plan was made for (the tail's share off)
  double predictedMs = 0.0;     ///< ms, the last plan's predicted frame
  std::vector<double> frameMs;  ///< each timed frame, ms
  double firstFrameMs = 0.0;  ///< the run's first frame, ms: the setting's first use (set-up, shader builds)
  std::vector<int> planChangeFrames;        ///< timed frames (index into frameMs) the plan changed in
  std::vector<int> warmupPlanChangeFrames;  ///< warm-up frames (0: the run's first) the plan changed in
  /// per timed frame (budget runs): the plan's predicted frame and the budget it was made for, ms
  std::vector<double> framePredictedMs, framePlannedForMs;
  std::vector<double> organRelRms;  ///< per organ (placements' order): rel RMS over its pixels
  /// per organ: AtlasScore's gain and shape rel RMS over its pixels (its level against the truth's,
  /// and its error once the level is matched)
  std::vector<double> organGain, organShapeRelRms;
  double interiorRelRms = 0.0;           ///< rel RMS over pixels off every silhouette (BudgetBenchResult)
  double gain = 0.0, shapeRelRms = 0.0;  ///< AtlasScore's: the overall level, the error once matched
  std::vector<LearnedOptionCost> learnedCosts;  ///< the controller's, at the last frame (budget runs)
  double learnedOverheadMs = 0.0;               ///< ms, the controller's frame overhead at the last frame
  bool tooSlow = false;  ///< a fixed setting stopped at a frame over maxFixedFrameMs (not scored)
};

/// One budget's row of the results.
struct BudgetResult {
  double budgetMs = 0.0;
  double frameMsMedian = 0.0, frameMsP95 = 0.0;
  double relRms = 0.0, relRmsDebiased = 0.0;
  double fixedBestRelRms = 0.0, fixedBestRelRmsDebiased = 0.0;  ///< NaN when no fixed setting fits
  /// "method setting" of the best fixed setting that fits: its p95 at most the budget, the
  /// target the controller plans for (docs/DECISIONS.md, "A fixed setting fits when its p95 does")
  std::string fixedBest;
  /// The same with the controller's 10 % allowance (p95 <= 1.1 budget), reported beside it; NaN,
  /// empty when none
  double fixedBestWithinTenPercentRelRms = 0.0;
  std::string fixedBestWithinTenPercent;
  bool withinTenPercent = false;  ///< frameMsP95 <= 1.1 budgetMs
  /// The controller's squared rel RMS minus the best fixed setting's, and its standard error from
  /// the truth's per-pixel noise (studies::errorDifference); NaN when no fixed setting fits.
  double squaredDifference = 0.0, squaredDifferenceStderr = 0.0;
  /// Lower than the best fixed setting by more than two of those standard errors (a difference the
  /// truth can resolve); true when no fixed setting fits.
  bool beatsFixed = false;
  /// Higher by more than two standard errors; neither: a tie within the truth's resolution.
  bool losesToFixed = false;
};

struct BudgetBenchResult {
  std::vector<BudgetRun> controller, fixed;
  std::vector<BudgetResult> results;
  int truthSpp = 0;
  double truthMs = 0.0, truthNoiseRelRms = 0.0;
  int organPixels = 0;
  /// Organ pixels whose 4 x 4 sub-pixel rays all meet the same organ: off the silhouettes, where
  /// the truth's jittered rays and the renderer's one sample per pixel see the same surface.
  int interiorPixels = 0;
  std::vector<std::string> organNames;  ///< the organs, in the scene's order
  std::vector<int> organPixelCounts;    ///< organ pixels per organ
  StudyOutput output;                   ///< budget_bench.json, .md, budget_bench.png (rel RMS against budget)
};

/// Runs the bench. Errors name the file or step.
Result<BudgetBenchResult> runBudgetBench(const BudgetBenchConfig& config);

}  // namespace tissue::studies
