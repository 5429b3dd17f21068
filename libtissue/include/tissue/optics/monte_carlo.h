#pragma once
/// \file
/// Monte Carlo photon transport in a stack of slabs, MCML's model (Wang, Jacques & Zheng 1995;
/// constants in shared/reference/monte_carlo_validation.md): a normal, collimated, infinitely
/// narrow beam; Henyey-Greenstein scattering; Fresnel reflection with total internal reflection at
/// every boundary; weight deposition dW = W mua/mut; Russian roulette below 1e-4 with survival 0.1.
///
/// Photons are run in independent batches. Each batch has its own random stream seeded from
/// (seed, batch index), so a result depends on the seed and the batch count only - not on the
/// thread count or on scheduling - and the batch totals give the standard errors.

#include <cstdint>
#include <functional>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/optics/medium.h"

namespace tissue::optics {

/// Annuli of width dr around the beam (MCML's radial grid).
struct RadialGrid {
  double drMm = 0.01;  ///< ring width, mm
  int bins = 100;      ///< rings; light leaving beyond bins * drMm counts in the totals only

  /// MCML's representative radius of ring i, mm: [(i + 1/2) + 1/(12 (i + 1/2))] dr (ring 0: 2/3 dr).
  double radius(int i) const;
  /// Area of ring i, mm^2: 2 pi (i + 1/2) dr^2.
  double area(int i) const;
};

/// How to run the simulation.
struct MonteCarloSettings {
  std::int64_t photons = 100000;  ///< photons in all (rounded up to a multiple of batches)
  std::uint64_t seed = 1;         ///< the random streams derive from it
  int batches = 20;               ///< independent batches for the standard errors (>= 2)
  int threads = 0;                ///< worker threads; 0: std::thread::hardware_concurrency()
  RadialGrid grid;                ///< radial scoring
  /// Hops (interactions and boundary hits) one photon may take before it is dropped. Without
  /// absorption (mua = 0) a photon in a half space ends only by escaping, and the time to escape
  /// of a random walk has an infinite mean (P(N > n) ~ n^-1/2), so one photon may run for hours.
  /// A dropped photon's weight is counted in cappedWeight, not in rd, tt or absorbed; photons
  /// that end normally (MCML's cases: thousands of hops at most) are unaffected.
  std::int64_t maxInteractions = 100000;
  /// Called on the calling thread about ten times a second with the fraction done in [0, 1];
  /// empty: no progress reports. The library never writes to stderr itself.
  std::function<void(double)> onProgress;
};

/// Tallies normalised per launched photon. The specular reflection is not in rd.
struct MonteCarloResult {
  double rd = 0.0;                 ///< diffuse reflectance (MCML's Rd), fraction of photons
  double rdStderr = 0.0;           ///< standard error of rd from the batch spread
  double tt = 0.0;                 ///< total transmittance, unscattered included
  double ttStderr = 0.0;           ///< standard error of tt
  double specular = 0.0;           ///< specular reflectance at the entry surface
  std::vector<double> absorbed;    ///< fraction absorbed per layer
  std::vector<double> radiusMm;    ///< representative radius per ring, mm
  std::vector<double> rdRadial;    ///< R_d(r) per ring, mm^-2
  std::vector<double> ttRadial;    ///< T(r) per ring, mm^-2 (zeros when the last layer is infinite)
  std::int64_t photons = 0;        ///< photons launched
  std::int64_t cappedPhotons = 0;  ///< photons dropped at maxInteractions hops
  double cappedWeight = 0.0;  ///< their weight, fraction of launched photons (rd + tt + absorbed + this = 1)
  int threads = 1;            ///< worker threads used
  double seconds = 0.0;       ///< wall-clock time of the run, s
};

/// Runs the simulation. Errors: an invalid medium or settings. Never throws.
Result<MonteCarloResult> simulateMonteCarlo(const LayeredMedium& medium, const MonteCarloSettings& settings);

}  // namespace tissue::optics
