#pragma once
/// \file
/// The figures of the trainee's loop (scene::OrganLoop, Scene::advance) as the reports give them:
/// the per-phase times, the instrument's force and the renderer's passes, as JSON text and
/// report tables (report.h). The main job (demo_run.h), replay (replay_run.h), tissue-sim render
/// and any host that reports its own run share them.

#include <string>

#include "tissue/render/renderer.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// `x` to three significant digits: figures for people to read (CSV files keep every digit).
/// 0, NaN and infinities come back unchanged.
double threeDigits(double x);

/// The loop's phases as a JSON array [{phase, median_ms, p99_ms, max_ms}], in the phases' order,
/// each figure threeDigits(ms).
std::string loopPhasesJson(const scene::LoopPhaseSamples& samples);

/// The same figures as a table: phase | median | p99 | max (ms, threeDigits), one row a phase.
Table loopPhasesTable(const scene::LoopPhaseSamples& samples);

/// The instrument's side of a loop record as a JSON object: frames, NaN frames and divergence
/// events; the largest and mean contact force (N); the deepest push and the strongest pull (N)
/// and their frames; the mean ms per frame of integration, contact and checks; and the force on
/// the tool every frame ("contact_force_N_per_frame": [[Fx, Fy, Fz], ...], N).
std::string instrumentJson(const scene::LoopRecord& record);

/// The renderer's last frame, pass by pass: a JSON array [{name, cpu_ms, gpu_ms}] in pass order
/// (gpu_ms -1 when the timers are off or the driver's value is impossible).
std::string passTimingsJson(const render::RenderTimings& timings);

}  // namespace tissue::studies
