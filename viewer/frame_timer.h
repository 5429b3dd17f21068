#pragma once
/// \file
/// The frame loop's named phases and their wall-clock cost: each phase is timed as it runs,
/// and the mean per phase (ms) is reported over a window of frames (about a second) and over
/// the whole run.

#include <array>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>

#include "tissue/core/stopwatch.h"

namespace tissue::viewer {

/// The phases of one frame, in the order the loop runs them.
/// Simulate, mesh, upload and render are scene::OrganLoop's phases (LoopPhases).
enum class Phase { Input, Simulate, Mesh, Upload, Render, Panel, Present };
inline constexpr std::size_t kPhaseCount = 7;
inline constexpr std::array<const char*, kPhaseCount> kPhaseNames{"input",  "simulate", "mesh",   "upload",
                                                                  "render", "panel",    "present"};

/// Sums of phase times (ms) over some frames.
struct PhaseTotals {
  std::array<double, kPhaseCount> ms{};
  long frames = 0;

  /// "input 0.01 | simulate 0.30 | ... ms" with the mean per frame of each phase.
  std::string summary() const {
    std::string out;
    char buffer[48];
    for (std::size_t i = 0; i < kPhaseCount; ++i) {
      std::snprintf(buffer, sizeof buffer, "%s%s %.2f", i ? " | " : "", kPhaseNames[i],
                    frames ? ms[i] / double(frames) : 0.0);
      out += buffer;
    }
    return out + " ms";
  }
};

/// Times the phases of each frame; reports means over the last window and the whole run.
class FrameTimer {
 public:
  /// Runs `work` as phase `phase` of the current frame and returns what it returns.
  template <class F>
  decltype(auto) time(Phase phase, F&& work) {
    const Stopwatch stopwatch;
    struct AddOnExit {  // also when `work` returns a value
      FrameTimer& timer;
      Phase phase;
      const Stopwatch& stopwatch;
      ~AddOnExit() { timer.add(phase, stopwatch.elapsedMs()); }
    } addOnExit{*this, phase, stopwatch};
    return std::forward<F>(work)();
  }

  /// Adds `ms` (ms) to `phase` of the current frame.
  void add(Phase phase, double ms) {
    m_window.ms[std::size_t(phase)] += ms;
    m_run.ms[std::size_t(phase)] += ms;
  }

  /// Closes the frame. Returns true when the report window (`windowS` seconds) is full.
  bool endFrame(double windowS = 1.0) {
    ++m_window.frames;
    ++m_run.frames;
    return m_windowClock.elapsedMs() >= windowS * 1000.0;
  }

  /// The window's totals and its frame rate (frames/s); starts a new window.
  std::pair<PhaseTotals, double> takeWindow() {
    const double seconds = m_windowClock.elapsedMs() / 1000.0;
    const PhaseTotals totals = m_window;
    m_last = m_window;
    m_window = {};
    m_windowClock.restart();
    return {totals, seconds > 0.0 ? double(totals.frames) / seconds : 0.0};
  }

  /// The mean ms of `phase` per frame over the last window taken (0 before the first).
  double lastMeanMs(Phase phase) const {
    return m_last.frames ? m_last.ms[std::size_t(phase)] / double(m_last.frames) : 0.0;
  }

  /// Totals over the whole run.
  const PhaseTotals& run() const { return m_run; }

 private:
  PhaseTotals m_window;
  PhaseTotals m_run;
  PhaseTotals m_last;  ///< the last window taken
  Stopwatch m_windowClock;
};

}  // namespace tissue::viewer
