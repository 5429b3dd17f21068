// The worker that builds organs' option settings off the frame path (option_preparer.h).
#include "option_preparer.h"

#include "tissue/scene/budget.h"

namespace tissue::scene::detail {

OptionPreparer::~OptionPreparer() {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  if (m_worker.joinable()) m_worker.join();
}

void OptionPreparer::add(PrepareJob job) {
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_jobs.push_back(std::move(job));
    if (!m_worker.joinable()) m_worker = std::thread([this] { work(); });
  }
  m_wake.notify_all();
}

std::vector<PreparedOption> OptionPreparer::collect() {
  std::unique_lock<std::mutex> lock(m_mutex, std::try_to_lock);
  if (!lock.owns_lock()) return {};  // the worker is handing one over: next frame
  std::vector<PreparedOption> out;
  out.swap(m_done);
  return out;
}

bool OptionPreparer::idle() {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_jobs.empty() && !m_busy;
}

void OptionPreparer::work() {
  // One option at a time; the lock is held to take an option and to hand it over, never during a
  // fit. The front job stays in place while its options are built: add() only appends, and a
  // deque's push_back keeps the front's address.
  std::unique_lock<std::mutex> lock(m_mutex);
  std::size_t next = 0;  // within the front job
  for (;;) {
    m_wake.wait(lock, [this] { return m_stop || !m_jobs.empty(); });
    if (m_stop) return;
    PrepareJob& job = m_jobs.front();
    if (next >= job.options.size()) {
      m_jobs.pop_front();
      next = 0;
      continue;
    }
    m_busy = true;
    lock.unlock();
    const auto& [index, option] = job.options[next];
    PreparedOption done{job.organ, index, methodOfOption(option, *job.assets, job.textures, job.choices)};
    lock.lock();
    m_busy = false;
    m_done.push_back(std::move(done));
    ++next;
  }
}

}  // namespace tissue::scene::detail
