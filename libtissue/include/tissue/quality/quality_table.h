#pragma once
/// \file
/// The quality controller's table (issue 16): every method and setting of the speed-accuracy
/// atlas (issue 13, studies/atlas.h) with its error against the path-traced truth per kind of
/// view, and a prior of its cost (a fixed part and a part per covered pixel), read from the
/// atlas's JSON (`tissue-sim atlas --json`: `results` [{method, setting, frame, ms, rel_rms,
/// rel_rms_debiased}], `truth.frames` [{frame, organ_pixels}]). GL-free; the scene maps the
/// names to the renderer's settings. Units: ms, px (pixels covered).

#include <array>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::quality {

/// The atlas frame an object's view resembles (studies/atlas.h frames; backlit is not used: the
/// controller does not know where the lights are).
enum class ViewClass { Rest, Deforming, CloseUp, Grazing, Oblique, Low };
inline constexpr std::size_t kViewClassCount = 6;
/// The atlas frame's name: "rest", "poked", "close-up", "grazing", "oblique", "low".
std::string_view viewClassFrame(ViewClass view);
/// The view class of an atlas frame's name; none for a frame the controller does not use (backlit).
std::optional<ViewClass> viewClassOfFrame(std::string_view frame);

/// The atlas frame that is the low frame's view from farther away (QualityOption::farRelRms).
inline constexpr std::string_view kFarFrame = "far";

/// No view angle known (QualityTable::viewAngleDeg).
inline constexpr double kNoAngle = std::numeric_limits<double>::quiet_NaN();

/// No pixel count known (QualityTable::framePx, farFramePx).
inline constexpr double kNoPixels = std::numeric_limits<double>::quiet_NaN();

/// The setting name of the fallback: lit with a wrap term (Unreal Substrate's Wrap tier).
inline constexpr std::string_view kWrapSetting = "wrap";

/// One method and setting.
struct QualityOption {
  std::string method;   ///< lit, separable, texture-space, ray-march, parallax
  std::string setting;  ///< the atlas's setting name ("preintegrated-17", "6g-opt", "50", ...; "wrap")
  /// Expected relative RMS error against the truth per ViewClass (the atlas's debiased rel RMS
  /// when the JSON has it); a class the atlas lacks takes the mean of the others (oblique: of
  /// rest and grazing where it has both, low: of oblique and grazing; the angles between them).
  std::array<double, kViewClassCount> relRms{};
  /// How well the atlas's truth resolved that error, per ViewClass: the standard error of the
  /// paired difference of squared rel RMS against the frame's best option (the atlas's
  /// `squared_vs_best_stderr`; studies::errorDifference). 0 where the JSON lacks it (and for the
  /// frame's best). Unitless (squared rel RMS).
  std::array<double, kViewClassCount> squaredStderr{};
  /// The atlas's far frame (the low frame's view from 2.5x the distance, ~100 organ pixels):
  /// the expected rel RMS and its standard error as the low frame's. Not a view class: it is the
  /// footprint axis at the low frame's angle (QualityTable::farFramePx, expectedSquaredError in
  /// controller.h). nan where the atlas lacks the frame.
  double farRelRms = std::numeric_limits<double>::quiet_NaN();
  double farSquaredStderr = 0.0;
  double fixedMs = 0.0;  ///< ms, the cost prior's part per object
  double msPerPx = 0.0;  ///< ms per covered pixel, the cost prior's part per pixel
  /// The options that run the same passes with other constants share one cost (costClassKey):
  /// the index of this option's class in QualityTable::costClasses (-1: a class of its own).
  int costClass = -1;
};

/// The cost class of an option: lit and its wrap term are one shader with one more uniform, and
/// the separable kernel models of one tap count are one shader with other weights (Jimenez et
/// al. 2015: the kernel is a uniform array; Freude's models change its values, not its length), so
/// they cost the same. "lit"; "separable-<taps>"; otherwise "<method> <setting>".
std::string costClassKey(std::string_view method, std::string_view setting);

/// The options and where they came from.
struct QualityTable {
  std::vector<QualityOption> options;
  /// ms, the atlas frame's cost that no method pays (clear, tone map, read back): the lit
  /// row's intercept, which the options' fixedMs are measured above.
  double frameOverheadMs = 0.0;
  std::string source;  ///< what it was read from, for reports
  /// degrees, per ViewClass: the view angle of its atlas frame (the atlas JSON's
  /// truth.frames[].view_angle_deg, as scene::organView measures it); nan where the atlas lacks
  /// the frame or its angle. The controller's error follows the angle between them
  /// (expectedSquaredError, controller.h).
  std::array<double, kViewClassCount> viewAngleDeg{kNoAngle, kNoAngle, kNoAngle,
                                                   kNoAngle, kNoAngle, kNoAngle};
  /// px, per ViewClass: the organ pixels of its atlas frame (truth.frames[].organ_pixels); nan
  /// where unknown. With farFramePx, the footprint axis of the controller's error.
  std::array<double, kViewClassCount> framePx{kNoPixels, kNoPixels, kNoPixels,
                                              kNoPixels, kNoPixels, kNoPixels};
  /// px, the far frame's organ pixels (QualityOption::farRelRms); nan where the atlas lacks it.
  double farFramePx = kNoPixels;
  /// The cost classes' keys (costClassKey), indexed by QualityOption::costClass.
  std::vector<std::string> costClasses;
  /// The option named (method, setting), or -1.
  int find(std::string_view method, std::string_view setting) const;
};

/// How an atlas becomes a table (plain struct with defaults).
struct TableSettings {
  bool debiased = true;  ///< use rel_rms_debiased (the truth's noise taken out) where given
  bool addWrap = true;   ///< add lit "wrap" (the atlas has no row for it: lit's errors, lit's cost)
};

/// The table from an atlas's JSON text. Errors name the missing key.
Result<QualityTable> qualityTableFromAtlasJson(std::string_view jsonText, const TableSettings& settings = {});
/// The same from a file (an atlas.json); errors name the file.
Result<QualityTable> loadQualityTable(const std::filesystem::path& atlasJson,
                                      const TableSettings& settings = {});
/// The committed default, data/quality/default_atlas.json (embedded at build time; its
/// README says which command produced it).
const QualityTable& defaultQualityTable();
/// The table of `atlasJson`, or the default where it is empty; an error where it does not load
/// or has no options (SceneSettings::qualityTable, the budget bench's --quality-table).
Result<QualityTable> qualityTableOrDefault(const std::filesystem::path& atlasJson);

}  // namespace tissue::quality
