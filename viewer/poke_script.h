#pragma once
/// \file
/// The scripted poke of `tissue-viewer --poke-script`: the right button as a script presses
/// it, so a headless run (or a demo) shows the tissue deforming without a mouse.

#include <cmath>
#include <cstdint>
#include <span>

#include "tissue/core/types.h"

namespace tissue::viewer {

/// The script's timing: the button goes down at `pressAtS` and up at `releaseAtS` of every
/// `periodS` seconds of simulated time.
struct PokeScript {
  double pressAtS = 0.1;    ///< s
  double releaseAtS = 0.9;  ///< s
  double periodS = 1.5;     ///< s
  double stepS = 1.0 / 30;  ///< s; simulated time per frame of a run with --frames

  /// Whether the scripted button is down at simulated time `timeS` (s).
  bool holds(double timeS) const {
    const double phase = std::fmod(timeS, periodS);
    return phase >= pressAtS && phase < releaseAtS;
  }
};

/// The scripted poke site: the vertex farthest along +z, which faces the home camera.
inline std::uint32_t topVertex(std::span<const Float3> positions) {
  std::uint32_t best = 0;
  for (std::uint32_t i = 1; i < positions.size(); ++i)
    if (positions[i].z > positions[best].z) best = i;
  return best;
}

}  // namespace tissue::viewer
