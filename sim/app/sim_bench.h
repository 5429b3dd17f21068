#pragma once
/// \file
/// The pieces of `tissue-sim sim-bench`: the step cost of every integrator on generated patches
/// (commands/sim_bench.cpp) and the whole per-frame path on an organ
/// (commands/sim_bench_frame_path.cpp).

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tissue/core/result.h"
#include "tissue/sim/system.h"

namespace tissue::sim_app {

/// Settings of the frame-path measurement.
struct FramePathOptions {
  std::filesystem::path mesh;  ///< organ (OBJ with UVs), mm
  int frames = 30;             ///< frames simulated per integrator (1/60 s each)
  int threads = 2;             ///< threads of the simulator and the mesh update
};

/// A bound on the largest natural angular frequency (rad/s) of `system` at rest, by
/// Gershgorin on M^-1/2 K M^-1/2: omega^2 <= max_i sum over i's springs k (1/m_i + 1/sqrt(m_i m_j)).
double omegaBound(const sim::MassSpringSystem& system);

/// One frame's simulation (symplectic Euler substepped below 2/omega_max, implicit Euler,
/// fast-mass-spring) (implicit Euler and fast-mass-spring), incremental plane re-fit
/// and tangent rebuild on `options.mesh`, mean ms per phase, as a JSON object.
Result<nlohmann::json> measureFramePath(const FramePathOptions& options);

}  // namespace tissue::sim_app
