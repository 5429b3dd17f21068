#pragma once
/// \file
/// The controller's learned costs (issue 16): each option's cost line, fitted online from measured
/// pass times, and the measured-over-prior ratios that calibrate options never measured. GL-free.
/// Units: ms, px (pixels covered).

#include <algorithm>
#include <array>
#include <limits>

#include "tissue/quality/quality_table.h"

namespace tissue::quality {

/// The weight of the newest of `samples` + 1 samples in every learned figure of the controller: a
/// running mean until 1 / learningRate samples, then an EMA of weight `learningRate` (started
/// without bias).
double sampleWeight(int samples, double learningRate);

/// A learned cost: ms = fixedMs + msPerPx * px up to fittedToPx, and beyondMsPerPx per pixel past
/// it, with the EMA'd normal equations behind it.
struct CostModel {
  double fixedMs = 0.0;  ///< ms
  double msPerPx = 0.0;  ///< ms per covered pixel
  /// px; the footprints the fitted line was measured over reach about this far (their mean plus
  /// two standard deviations). A slope fitted between objects of 30 and 60 px is their timing
  /// noise as much as their cost: extrapolated to a 5000 px close-up it priced lit at 50 ms (the
  /// fallback tier's far organs were lit's only samples). Past it, the lesser of the fitted and
  /// the prior's slope (beyondMsPerPx). Infinite while the line is the prior's shape.
  double fittedToPx = std::numeric_limits<double>::infinity();
  double beyondMsPerPx = 0.0;  ///< ms per covered pixel past fittedToPx
  // Exponentially weighted sums of 1, px, px^2, ms, px ms (the normal equations).
  double w = 0.0, wx = 0.0, wxx = 0.0, wy = 0.0, wxy = 0.0;
  double priorFixedMs = 0.0, priorMsPerPx = 0.0;  ///< the shape kept while px hardly varies
  int samples = 0;
  double predictMs(double px) const {
    return fixedMs + msPerPx * std::min(px, fittedToPx) + beyondMsPerPx * std::max(0.0, px - fittedToPx);
  }
};
/// A cost model starting at the table's prior.
CostModel costModelOf(const QualityOption& option);
/// One measured sample: `ms` spent on an object of `px` covered pixels. The fit is the
/// exponentially weighted least squares of (1, px) -> ms, over the footprints it was measured at
/// (CostModel::fittedToPx); while the samples' px hardly vary it keeps the prior's shape and
/// scales it to the measured level.
void observeCost(CostModel& model, double px, double ms, double learningRate);

/// Measured cost over the table's prior, one ratio per cost term: ms = f x (the prior's fixed
/// part) + p x (the prior's per-pixel part x px). One ratio for both terms is wrong where the
/// measured samples and the option it calibrates split their cost differently: a per-pixel line
/// fitted at the atlas's few thousand pixels and extrapolated to a large footprint (texture
/// space's depth-sized maps, whose size is capped) measures far below it, and that ratio must not
/// price a sibling whose cost is a fixed map size (the uncut maps). Each sample's ratio (measured
/// over its prior) is credited to each term by the square of that term's share of the prior,
/// with a pseudo-weight of 0.01 on a fallback: samples whose cost is one term's teach that term
/// alone, and a term no sample spends more than about a tenth of its cost on keeps the fallback.
/// (A least-squares fit of both terms is what the normal equations would give, but samples of
/// nearly one cost split with different ratios, two methods pooled, make it swing without bound.)
struct CostTermRatios {
  // Exponentially weighted means of a^2, a^2 r, b^2, b^2 r: a, b the terms' shares of the
  // sample's prior, r its measured-over-prior ratio.
  double saa = 0.0, saar = 0.0, sbb = 0.0, sbbr = 0.0;
  int samples = 0;
};
/// One measured sample: `ms` where the prior said `priorFixedMs` + `priorPixelMs` (ms each).
void observeTermRatios(CostTermRatios& ratios, double priorFixedMs, double priorPixelMs, double ms,
                       double learningRate);
/// {f, p}, each in [0.05, 20]: the credited ratios, the fallback's weight 0.01 beside them.
std::array<double, 2> termRatiosOf(const CostTermRatios& ratios, std::array<double, 2> fallback);

}  // namespace tissue::quality
