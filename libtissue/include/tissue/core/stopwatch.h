#pragma once
/// \file
/// Wall-clock timing for named frame phases and benchmarks.

#include <chrono>

namespace tissue {

/// Measures elapsed wall-clock time in milliseconds since construction or the last restart().
class Stopwatch {
 public:
  Stopwatch() : m_start(Clock::now()) {}
  void restart() { m_start = Clock::now(); }
  /// Milliseconds since the start.
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - m_start).count();
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point m_start;
};

}  // namespace tissue
