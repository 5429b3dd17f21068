#pragma once
/// \file
/// The soak run (issue 14, item 5): a recorded session replayed over and over, each frame one
/// pass of the trainee's loop (simulate, mesh, upload, render, read back), the shading method
/// switched in turn through all five, for as many frames as asked (100,000 by default). After the
/// warm-up the process's resident memory (sampled after core/process_memory.h's releaseFreeHeap,
/// so that a transient heap peak's pages the allocator keeps do not count) may grow by at most 1 MB and the
/// GL objects alive in the context (counted by asking GL, gl::countLiveObjects) must stay the same. A
/// benchmark-style run, not a test: tissue-sim soak parses, calls and prints.

#include <filesystem>
#include <functional>
#include <string>

#include "tissue/core/result.h"
#include "tissue/scene/scene.h"

namespace tissue::studies {

/// What to soak (plain struct with defaults).
struct SoakConfig {
  std::filesystem::path session{};  ///< data/sessions/*.json, replayed cyclically
  long frames = 100000;             ///< frames in all
  long warmupFrames = 5000;         ///< after these the memory and GL baselines are taken
  long sampleEvery = 1000;          ///< frames between two samples of memory and GL objects
  long methodEvery = 200;           ///< frames per shading method, all five in turn (0: lit only)
  int width = 96;                   ///< pixels of each rendered frame
  int height = 72;                  ///< pixels
  /// Texels a side of the texture-space irradiance map and the parallax lightmap: their
  /// lifecycle is what a soak checks, and at the methods' 1024 they make llvmpipe's frame 3x dearer.
  int mapSize = 256;
  double rssBudgetKb = 1024.0;                           ///< kB, the growth allowed after warm-up
  std::function<void(const std::string&)> onProgress{};  ///< a line per sample (empty: none)
};

/// Runs the soak in a scene of `scene`'s settings (its methods' map sizes replaced by mapSize) on
/// its own headless context. Returns the report
/// as a JSON object's text: session, frames, warmup_frames, method_every, width, height, frame_ms
/// {median, p99, max}, rss_kb {after_warmup, end, max, floor_first_quarter, floor_last_quarter,
/// growth = the last quarter's floor less the first's (a leak raises the floor), peak_growth},
/// gl_objects {after_warmup, end,
/// min, max, by_kind}, heap_kb {after_warmup, end} (core/process_memory.h), samples [{frame,
/// rss_kb, heap_kb, gl_objects}], divergence_events, nan_frames and
/// the verdicts rss_ok (growth <= rssBudgetKb) and gl_ok (constant). Errors: bad counts (the
/// warm-up must see every method once), a session of another mesh, a failed frame (named).
Result<std::string> soakSession(const SoakConfig& config, const scene::SceneSettings& scene);

}  // namespace tissue::studies
