// The controller's learned costs (cost_model.h): each option's line and the per-term ratios.
#include "tissue/quality/cost_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tissue::quality {
double sampleWeight(int samples, double learningRate) {
  return std::clamp(std::max(learningRate, 1.0 / double(samples + 1)), 0.0, 1.0);
}

CostModel costModelOf(const QualityOption& option) {
  CostModel m;
  m.fixedMs = m.priorFixedMs = option.fixedMs;
  m.msPerPx = m.priorMsPerPx = option.msPerPx;
  return m;
}

void observeCost(CostModel& m, double px, double ms, double learningRate) {
  if (!std::isfinite(px) || !std::isfinite(ms)) return;
  const double a = sampleWeight(m.samples, learningRate);
  m.w = (1 - a) * m.w + a;
  m.wx = (1 - a) * m.wx + a * px;
  m.wxx = (1 - a) * m.wxx + a * px * px;
  m.wy = (1 - a) * m.wy + a * ms;
  m.wxy = (1 - a) * m.wxy + a * px * ms;
  ++m.samples;
  const double mx = m.wx / m.w, my = m.wy / m.w;
  const double var = m.wxx / m.w - mx * mx;
  const double cov = m.wxy / m.w - mx * my;
  const double prior = m.priorFixedMs + m.priorMsPerPx * mx;
  if (m.samples >= 3 && var > (0.05 * mx) * (0.05 * mx) && var > 1e-12) {
    const double b = cov / var;
    if (b >= 0.0) {
      m.msPerPx = b;
      m.fixedMs = my - b * mx;
      if (m.fixedMs < 0.0) {  // through the origin instead
        m.fixedMs = 0.0;
        m.msPerPx = m.wxy / std::max(m.wxx, 1e-30);
      }
      // Past the measured footprints, the prior's slope. Not scaled by the measured level: that
      // level is mostly the per-object work a small object pays (lit's prior, above the frame's
      // overhead, has none), 60x its prior at 45 px, which says nothing of the cost per pixel.
      m.fittedToPx = mx + 2.0 * std::sqrt(var);
      m.beyondMsPerPx = std::min(m.msPerPx, m.priorMsPerPx);
      return;
    }
  }
  // The px hardly vary: the prior's shape, scaled to the measured level.
  m.fittedToPx = std::numeric_limits<double>::infinity();
  m.beyondMsPerPx = 0.0;
  if (prior > 1e-12) {
    const double k = my / prior;
    m.fixedMs = k * m.priorFixedMs;
    m.msPerPx = k * m.priorMsPerPx;
  } else {
    m.fixedMs = my;
    m.msPerPx = 0.0;
  }
}

void observeTermRatios(CostTermRatios& r, double a, double b, double ms, double learningRate) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(ms) || a < 0.0 || b < 0.0 || a + b <= 1e-12)
    return;
  const double s = a + b;
  const double ratio = std::clamp(ms / s, 0.05, 20.0);  // one stalled frame is not a machine
  a /= s;
  b /= s;
  const double w = sampleWeight(r.samples, learningRate);
  r.saa = (1 - w) * r.saa + w * a * a;
  r.saar = (1 - w) * r.saar + w * a * a * ratio;
  r.sbb = (1 - w) * r.sbb + w * b * b;
  r.sbbr = (1 - w) * r.sbbr + w * b * b * ratio;
  ++r.samples;
}

std::array<double, 2> termRatiosOf(const CostTermRatios& r, std::array<double, 2> fallback) {
  constexpr double kFallbackWeight = 0.01;  // a term's squared share of about a tenth
  const auto credited = [&](double ss, double ssr, double f0) {
    return std::clamp((ssr + kFallbackWeight * f0) / (ss + kFallbackWeight), 0.05, 20.0);
  };
  return {credited(r.saa, r.saar, fallback[0]), credited(r.sbb, r.sbbr, fallback[1])};
}

}  // namespace tissue::quality
