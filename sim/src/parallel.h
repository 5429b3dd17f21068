#pragma once
// A plain fork-join over index ranges for the force passes. Each item is written by exactly one
// thread and nothing is reduced across threads, so the results are bit-identical for any count.

#include <algorithm>
#include <cstddef>
#include <system_error>
#include <thread>
#include <vector>

namespace tissue::sim::detail {

/// Below this many items a pass runs on the calling thread (thread start-up costs ~10-50 us).
inline constexpr std::size_t kMinParallelItems = 8192;

/// Calls body(begin, end) over [0, n) split into `threads` contiguous ranges; the calling thread
/// takes the first. When a thread cannot be started its range runs on the calling thread.
template <class Body>
void parallelRanges(std::size_t n, int threads, const Body& body) {
  const std::size_t parts = std::clamp<std::size_t>(threads > 0 ? static_cast<std::size_t>(threads) : 1, 1,
                                                    std::max<std::size_t>(1, n / (kMinParallelItems / 2)));
  if (parts <= 1 || n < kMinParallelItems) {
    body(std::size_t{0}, n);
    return;
  }
  std::vector<std::jthread> workers;
  workers.reserve(parts - 1);
  for (std::size_t p = 1; p < parts; ++p) {
    const std::size_t begin = n * p / parts, end = n * (p + 1) / parts;
    try {
      workers.emplace_back([&body, begin, end] { body(begin, end); });
    } catch (const std::system_error&) {
      body(begin, end);
    }
  }
  body(std::size_t{0}, n / parts);
}

}  // namespace tissue::sim::detail
