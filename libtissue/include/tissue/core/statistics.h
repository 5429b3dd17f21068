#pragma once
/// \file
/// Order statistics of per-frame costs (ms) for reports and benchmarks: median, p99, max.

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace tissue {

/// Median, 99th percentile (nearest rank), maximum and mean of a sample; zeros when empty.
struct SampleSummary {
  double median = 0.0;
  double p99 = 0.0;
  double max = 0.0;
  double mean = 0.0;
  std::size_t count = 0;
};

/// The value at quantile q in [0, 1] of `sorted` (ascending) by the nearest-rank method.
inline double quantileSorted(std::span<const double> sorted, double q) {
  if (sorted.empty()) return 0.0;
  const double rank = std::ceil(q * static_cast<double>(sorted.size()));
  const std::size_t index = rank < 1.0 ? 0 : static_cast<std::size_t>(rank) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

/// The value at quantile q in [0, 1] of `values` (any order; copied) by the nearest-rank
/// method; 0 when empty.
inline double quantile(std::span<const double> values, double q) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return quantileSorted(sorted, q);
}

/// Summarises `samples` (any order; copied).
inline SampleSummary summarizeSamples(std::span<const double> samples) {
  SampleSummary s;
  s.count = samples.size();
  if (samples.empty()) return s;
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  s.p99 = quantileSorted(sorted, 0.99);
  s.max = sorted.back();
  double sum = 0.0;
  for (double x : sorted)
    sum += x;
  s.mean = sum / static_cast<double>(n);
  return s;
}

}  // namespace tissue
