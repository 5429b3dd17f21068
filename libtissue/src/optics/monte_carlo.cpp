// Batches of MCML photons on std::threads, merged in batch order (monte_carlo.h).
#include "tissue/optics/monte_carlo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <system_error>
#include <thread>

#include "photon_batch.h"

namespace tissue::optics {

double RadialGrid::radius(int i) const {
  // MCML's representative radius: the ring's centre of mass, to second order.
  if (i == 0) return 2.0 / 3.0 * drMm;
  const double c = i + 0.5;
  return (c + 1.0 / (12.0 * c)) * drMm;
}

double RadialGrid::area(int i) const {
  return 2.0 * std::numbers::pi * (i + 0.5) * drMm * drMm;
}

namespace {

Result<void> validateSettings(const MonteCarloSettings& s) {
  if (s.photons < 1) return Error{"Monte Carlo: photons must be >= 1; pass a positive count"};
  if (s.batches < 2) return Error{"Monte Carlo: batches must be >= 2 to estimate standard errors"};
  if (s.threads < 0) return Error{"Monte Carlo: threads must be >= 0 (0: all cores)"};
  if (!(s.grid.drMm > 0.0) || s.grid.bins < 1)
    return Error{"Monte Carlo: radial grid needs dr > 0 mm and bins >= 1"};
  if (s.maxInteractions < 1) return Error{"Monte Carlo: maxInteractions must be >= 1 hop per photon"};
  return {};
}

// Mean and standard error of the batch means (equal batch sizes).
void meanAndStderr(const std::vector<double>& values, double& mean, double& stderrOut) {
  const double n = static_cast<double>(values.size());
  double sum = 0;
  for (double v : values)
    sum += v;
  mean = sum / n;
  double ss = 0;
  for (double v : values)
    ss += (v - mean) * (v - mean);
  stderrOut = std::sqrt(ss / (n * (n - 1.0)));
}

// Runs every batch on `threads` workers; a worker takes the next batch index from a counter.
Result<void> runBatches(const LayeredMedium& medium, const MonteCarloSettings& settings,
                        std::int64_t perBatch, int threads, std::vector<detail::BatchTally>& tallies) {
  std::atomic<int> nextBatch{0};
  std::atomic<int> finished{0};
  std::atomic<std::int64_t> progress{0};
  auto worker = [&] {
    for (int b = nextBatch.fetch_add(1); b < settings.batches; b = nextBatch.fetch_add(1)) {
      tallies[static_cast<std::size_t>(b)] =
          detail::runPhotonBatch(medium, settings.grid, perBatch, settings.maxInteractions, settings.seed,
                                 static_cast<std::uint64_t>(b), progress);
      finished.fetch_add(1);
    }
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 0; t < threads; ++t)
      pool.emplace_back(worker);
  } catch (const std::system_error& e) {
    nextBatch.store(settings.batches);  // the started workers finish their batch and stop
    for (auto& th : pool)
      th.join();
    return Error{std::string("Monte Carlo: could not start a worker thread: ") + e.what() +
                 "; try --threads 1"};
  }
  const double total = static_cast<double>(perBatch) * settings.batches;
  while (settings.onProgress && finished.load() < settings.batches) {
    settings.onProgress(static_cast<double>(progress.load()) / total);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (auto& th : pool)
    th.join();
  if (settings.onProgress) settings.onProgress(1.0);
  return {};
}

}  // namespace

Result<MonteCarloResult> simulateMonteCarlo(const LayeredMedium& medium, const MonteCarloSettings& settings) {
  if (auto ok = validateMedium(medium); !ok) return ok.error();
  if (auto ok = validateSettings(settings); !ok) return ok.error();
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t perBatch = (settings.photons + settings.batches - 1) / settings.batches;
  int threads =
      settings.threads > 0 ? settings.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, settings.batches);

  std::vector<detail::BatchTally> tallies(static_cast<std::size_t>(settings.batches));
  if (auto ok = runBatches(medium, settings, perBatch, threads, tallies); !ok) return ok.error();

  // Merge in batch order, so that the sums do not depend on scheduling.
  MonteCarloResult out;
  out.photons = perBatch * settings.batches;
  out.threads = threads;
  out.specular = specularReflectance(medium);
  const double n = static_cast<double>(out.photons);
  const auto bins = static_cast<std::size_t>(settings.grid.bins);
  out.absorbed.assign(medium.layers.size(), 0.0);
  out.rdRadial.assign(bins, 0.0);
  out.ttRadial.assign(bins, 0.0);
  std::vector<double> rdBatch, ttBatch;
  for (const auto& t : tallies) {
    rdBatch.push_back(t.rd / static_cast<double>(perBatch));
    ttBatch.push_back(t.tt / static_cast<double>(perBatch));
    out.cappedPhotons += t.capped;
    out.cappedWeight += t.cappedWeight / n;
    for (std::size_t l = 0; l < t.absorbed.size(); ++l)
      out.absorbed[l] += t.absorbed[l] / n;
    for (std::size_t i = 0; i < bins; ++i) {
      out.rdRadial[i] += t.rdRing[i];
      out.ttRadial[i] += t.ttRing[i];
    }
  }
  meanAndStderr(rdBatch, out.rd, out.rdStderr);
  meanAndStderr(ttBatch, out.tt, out.ttStderr);
  // Radial scoring per unit area (MCML): weight / (ring area * photons).
  for (std::size_t i = 0; i < bins; ++i) {
    const int ring = static_cast<int>(i);
    out.radiusMm.push_back(settings.grid.radius(ring));
    out.rdRadial[i] /= settings.grid.area(ring) * n;
    out.ttRadial[i] /= settings.grid.area(ring) * n;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tissue::optics
