#include "tissue/mesh/worker_pool.h"

#include <algorithm>

namespace tissue::mesh {

WorkerPool::WorkerPool(unsigned threadCount) {
  if (threadCount == 0) threadCount = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  m_workers.reserve(threadCount - 1);
  for (unsigned i = 1; i < threadCount; ++i)
    m_workers.emplace_back([this, i] { workerLoop(i); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  for (auto& w : m_workers)
    w.join();
}

void WorkerPool::run(std::size_t count, std::size_t minChunk, Job job, void* context) {
  const std::size_t byWork = count / std::max<std::size_t>(minChunk, 1);
  const unsigned chunks = unsigned(std::clamp<std::size_t>(byWork, 1, threadCount()));
  if (chunks == 1) {
    job(context, 0, count);
    return;
  }
  // Hand chunks 1.. to the workers, run chunk 0 here, then wait for the rest.
  {
    std::lock_guard lock(m_mutex);
    m_job = job, m_context = context, m_count = count, m_chunks = chunks;
    m_pending = unsigned(m_workers.size());
    ++m_generation;
  }
  m_wake.notify_all();
  job(context, 0, chunkBegin(count, chunks, 1));
  std::unique_lock lock(m_mutex);
  m_finished.wait(lock, [this] { return m_pending == 0; });
}

void WorkerPool::workerLoop(unsigned index) {
  std::uint64_t seen = 0;
  for (;;) {
    std::unique_lock lock(m_mutex);
    m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
    if (m_stop) return;
    seen = m_generation;
    const Job job = m_job;
    void* const context = m_context;
    const std::size_t count = m_count;
    const unsigned chunks = m_chunks;
    lock.unlock();
    if (index < chunks) job(context, chunkBegin(count, chunks, index), chunkBegin(count, chunks, index + 1));
    lock.lock();
    if (--m_pending == 0) m_finished.notify_one();
  }
}

}  // namespace tissue::mesh
