#pragma once
// A plain fork-join over index ranges for the spring and vector passes. Each item is written by
// exactly one thread, and sums are reduced over fixed blocks in a fixed order, so the results
// are bit-identical for any thread count.

#include <algorithm>
#include <cstddef>
#include <system_error>
#include <thread>
#include <vector>

namespace tissue::sim::detail {

/// Below this many items a pass runs on the calling thread (thread start-up costs ~10-50 us).
inline constexpr std::size_t kMinParallelItems = 8192;
/// Items per partial sum of parallelSum (fixed, so the rounding does not depend on threads).
inline constexpr std::size_t kSumBlock = 4096;

/// Calls body(begin, end) over [0, n) split into `threads` contiguous ranges; the calling thread
/// takes the first. Runs on the calling thread alone below `minItems` items. When a thread
/// cannot be started its range runs on the calling thread.
template <class Body>
void parallelRanges(std::size_t n, int threads, const Body& body, std::size_t minItems = kMinParallelItems) {
  const std::size_t parts =
      std::clamp<std::size_t>(threads > 0 ? static_cast<std::size_t>(threads) : 1, 1,
                              std::max<std::size_t>(1, n / std::max<std::size_t>(1, minItems / 2)));
  if (parts <= 1 || n < minItems) {
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

/// Sum of term(k) over [0, n): partial sums over fixed blocks of kSumBlock items, added in block
/// order. The same bits for any thread count (not the bits of a plain left-to-right sum).
template <class Term>
double parallelSum(std::size_t n, int threads, const Term& term) {
  const std::size_t blocks = (n + kSumBlock - 1) / kSumBlock;
  std::vector<double> partial(blocks, 0.0);
  parallelRanges(
      blocks, threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b) {
          double s = 0.0;
          for (std::size_t k = b * kSumBlock, e = std::min(n, (b + 1) * kSumBlock); k < e; ++k)
            s += term(k);
          partial[b] = s;
        }
      },
      2 * kMinParallelItems / kSumBlock);
  double total = 0.0;
  for (double s : partial)
    total += s;
  return total;
}

}  // namespace tissue::sim::detail
