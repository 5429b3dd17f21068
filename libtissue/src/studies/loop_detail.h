#pragma once
// Private to tissue::studies: loop_report.h's figures as nlohmann-json values, for the reports
// that build on them (demo_run.cpp, replay_run.cpp, render_summary.cpp), and the scene the main
// job and replay run their loop in.

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "tissue/context/gl_context.h"
#include "tissue/core/result.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/scene.h"

namespace tissue::studies::detail {

/// {median, p99, max} of `ms`, each threeDigits.
nlohmann::json msSummary(const std::vector<double>& ms);
nlohmann::json loopPhases(const scene::LoopPhaseSamples& samples);
nlohmann::json instrument(const scene::LoopRecord& record);
nlohmann::json passTimings(const render::RenderTimings& timings);

/// A scene on `context` (its context current) drawing lit without MSAA or GPU timers, as a
/// trainee's frame costs; with no context, the simulation only (SceneSettings::gl = false).
Result<scene::Scene> makeLoopScene(const context::GlContext* context, scene::SceneSettings settings);

/// A headless context of `settings` (backend, EGL platform) for scenes that draw into their own
/// targets (a 16 x 16 default buffer), made current; `log`: one stderr line naming it.
Result<std::unique_ptr<context::GlContext>> offscreenContext(const scene::SceneSettings& settings, bool log);

}  // namespace tissue::studies::detail
