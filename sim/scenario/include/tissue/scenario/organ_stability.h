#pragma once
/// \file
/// The stability study on the organ (issue 11): for each integrator and Young's modulus, the
/// largest frame step at which a scenario (the default: the volumetric liver under the scripted
/// poke) runs without divergence, with the degrade switched off so that failures show; and what
/// each integrator costs per 1/60 s frame to stay stable (the substeps it needs, timed).
/// The one-spring study (tissue/sim/stability_study.h) checks the integrators against theory;
/// this one says what they cost on the scene the product runs.

#include <optional>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/scenario/scenario.h"

namespace tissue::scenario {

/// The study's grid and search (plain struct with defaults).
struct OrganStabilityConfig {
  std::vector<double> youngsModuliKpa{2.0, 5.0, 20.0, 80.0};  ///< kPa
  std::vector<sim::Integrator> integrators{sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler,
                                           sim::Integrator::VelocityVerlet, sim::Integrator::ImplicitEuler,
                                           sim::Integrator::FastMassSpring};
  double windowS = 3.5;          ///< s simulated per trial: the approach and the deepest poke
  double minStepS = 1e-4;        ///< s, smallest frame step tried (0.1 ms: 35,000 steps per 3.5 s window)
  double maxStepS = 1.0 / 30.0;  ///< s, largest frame step tried (two 60 Hz frames)
  int bisections = 6;            ///< halvings of the log-step interval after the bracket (to 1/64 of its
                                 ///< log range: about 8% in step)
  double frameS = 1.0 / 60.0;    ///< s, the render frame the cost is measured for
  int maxSubsteps = 1024;        ///< the cost search gives up beyond this many substeps per frame
};

/// One integrator at one modulus.
struct OrganStabilityRow {
  sim::Integrator integrator{};
  double youngsModulusKpa = 0.0;  ///< kPa
  /// s: the largest frame step (one substep) found stable; none when even minStepS diverged.
  std::optional<double> maxStableStepS;
  bool stableAtMaxTested = false;  ///< stable at maxStepS: the limit lies beyond what was tried
  /// Substeps per frameS frame that ran the window without divergence; none beyond maxSubsteps.
  std::optional<int> substepsPerFrame;
  double msPerFrameMedian = 0.0;  ///< ms of wall time per frameS frame at those substeps (median)
  double msPerFrameMax = 0.0;     ///< ms, the slowest frame of the window
  int trials = 0;                 ///< runs made for this row
};

/// Whether `scenario` runs `windowS` seconds at frame step `stepS` (one substep, the degrade
/// off) with no divergence event and no non-finite value.
Result<bool> runsStably(const Scenario& scenario, double stepS, int substeps, double windowS);

/// Runs the study on `base` (which must give its tissue as material constants: the study sets E).
/// Fails, naming the file, when it does not, or when the scenario cannot be built.
Result<std::vector<OrganStabilityRow>> runOrganStabilityStudy(const Scenario& base,
                                                              const OrganStabilityConfig& config = {});

}  // namespace tissue::scenario
