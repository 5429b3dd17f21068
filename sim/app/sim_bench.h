#pragma once
/// \file
/// The pieces of `tissue-sim sim-bench`: the step cost of every integrator on generated patches
/// (commands/sim_bench.cpp) and the whole per-frame path on an organ
/// (commands/sim_bench_frame_path.cpp).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "tissue/core/result.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/system.h"

namespace tissue::sim_app {

/// Settings of the frame-path measurement.
struct FramePathOptions {
  std::filesystem::path mesh;  ///< organ (OBJ with UVs), mm
  int frames = 30;             ///< frames simulated per integrator (1/60 s each)
  int threads = 2;             ///< threads of the simulator and the mesh update
};

/// Settings of the scenario measurement.
struct ScenarioBenchOptions {
  std::filesystem::path scenario;         ///< scenario file (default data/scenarios/liver_poke_grasp.json)
  std::filesystem::path sharedMeshesDir;  ///< ../shared/meshes, for relative mesh paths
  int frames = 0;                         ///< 0: the scenario's
  std::optional<sim::Integrator> integrator;  ///< instead of the scenario's
};

/// Runs a scenario as `simulate` does (contact and grasp included) and reports ms per frame
/// and per substep (median, p99, max), the force-update rate (Hz: force samples per simulated
/// second), divergence events, degraded frames, the largest force (N) and refactoring (ms).
Result<nlohmann::json> measureScenario(const ScenarioBenchOptions& options);

/// One frame's simulation (symplectic Euler substepped below 2/omega_max, implicit Euler,
/// fast-mass-spring) (implicit Euler and fast-mass-spring), incremental plane re-fit
/// and tangent rebuild on `options.mesh`, mean ms per phase, as a JSON object.
Result<nlohmann::json> measureFramePath(const FramePathOptions& options);

}  // namespace tissue::sim_app
