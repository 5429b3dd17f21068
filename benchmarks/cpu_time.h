#pragma once
// CPU seconds of the benchmark process, so that rates are per core whatever else loads the
// machine (the benches run one worker thread; MCML is timed by its user time).
#include <ctime>

namespace tissue::bench {

inline double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace tissue::bench
