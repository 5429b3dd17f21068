#pragma once
/// \file
/// What `demo` and `replay` share around the library's loop: a scene of the project's data
/// (scene::Scene with data/materials/, the shared meshes, the app's shaders) whose simulated
/// organ the library runs frame by frame, and the per-phase figures of a run for the reports.

#include <nlohmann/json.hpp>

#include "tissue/context/gl_context.h"
#include "tissue/core/result.h"
#include "tissue/scene/scene.h"

namespace tissue::sim_app {

/// A scene on `context` (its context current) drawing lit without MSAA or GPU timers, as a
/// trainee's frame costs; with no context, the simulation only (SceneSettings::gl = false).
Result<scene::Scene> makeLoopScene(const context::GlContext* context);

/// A context for scenes that draw into their own targets (a 16 x 16 default buffer).
context::ContextRequest offscreenRequest();

/// Three significant digits: figures for people to read (CSV files keep every digit).
double rounded(double x);

/// [{phase, median_ms, p99_ms, max_ms}] with rounded figures.
nlohmann::json phaseReport(const scene::LoopPhaseSamples& samples);

}  // namespace tissue::sim_app
