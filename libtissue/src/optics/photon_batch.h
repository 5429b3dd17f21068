#pragma once
// Private: one batch of MCML photons, run on one thread with its own random stream.

#include <atomic>
#include <cstdint>
#include <vector>

#include "tissue/optics/monte_carlo.h"

namespace tissue::optics::detail {

/// Raw weight sums of one batch (not yet divided by photons or ring areas).
struct BatchTally {
  double rd = 0.0;               ///< weight leaving through the top, specular excluded
  double tt = 0.0;               ///< weight leaving through the bottom
  std::vector<double> absorbed;  ///< weight absorbed per layer
  std::vector<double> rdRing;    ///< reflected weight per ring
  std::vector<double> ttRing;    ///< transmitted weight per ring
  std::int64_t capped = 0;       ///< photons dropped at the hop cap
  double cappedWeight = 0.0;     ///< their weight
};

/// Runs `photons` photons through the validated `medium` with the stream (seed, stream), adding
/// to `progress` every 1024 photons. A photon still alive after `maxInteractions` hops is
/// dropped and counted in `capped`.
BatchTally runPhotonBatch(const LayeredMedium& medium, const RadialGrid& grid, std::int64_t photons,
                          std::int64_t maxInteractions, std::uint64_t seed, std::uint64_t stream,
                          std::atomic<std::int64_t>& progress);

}  // namespace tissue::optics::detail
