#pragma once
/// \file
/// A small persistent pool of threads for the per-frame shading loops: starting threads every
/// frame would cost more than the work on a mesh of a few ten thousand vertices.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace tissue::mesh {

/// Splits index ranges over a fixed set of threads (the caller's thread is one of them).
/// Each index is processed by exactly one thread, so loops whose items are independent give
/// the same result for any thread count.
class WorkerPool {
 public:
  /// \param threadCount  threads in all, the caller's included; 0 picks the hardware's
  ///                     concurrency (at most 8), 1 runs everything on the caller's thread
  explicit WorkerPool(unsigned threadCount = 0);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Threads in all, the caller's included.
  unsigned threadCount() const { return unsigned(m_workers.size()) + 1; }

  /// Calls body(begin, end) on contiguous chunks covering [0, count), one per thread but
  /// none smaller than `minChunk` items, and returns when all are done.
  template <class Body>
  void parallelFor(std::size_t count, std::size_t minChunk, Body&& body) {
    using B = std::remove_reference_t<Body>;
    run(
        count, minChunk, [](void* ctx, std::size_t b, std::size_t e) { (*static_cast<B*>(ctx))(b, e); },
        const_cast<void*>(static_cast<const void*>(&body)));
  }

 private:
  using Job = void (*)(void*, std::size_t, std::size_t);
  void run(std::size_t count, std::size_t minChunk, Job job, void* context);
  void workerLoop(unsigned index);
  static std::size_t chunkBegin(std::size_t count, unsigned chunks, unsigned chunk) {
    return count * chunk / chunks;
  }

  std::vector<std::thread> m_workers;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::condition_variable m_finished;
  std::uint64_t m_generation = 0;  // bumped for every job handed to the workers
  unsigned m_pending = 0;          // workers still busy with the current job
  bool m_stop = false;
  Job m_job = nullptr;
  void* m_context = nullptr;
  std::size_t m_count = 0;
  unsigned m_chunks = 0;
};

/// Runs body(begin, end) over [0, count): on `pool` when there is one, else serially.
template <class Body>
void parallelFor(WorkerPool* pool, std::size_t count, std::size_t minChunk, Body&& body) {
  if (pool)
    pool->parallelFor(count, minChunk, body);
  else
    body(std::size_t(0), count);
}

}  // namespace tissue::mesh
