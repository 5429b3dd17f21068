// The organs' offered options and their settings, built on one worker thread (option_catalog.h).
#include "tissue/scene/option_catalog.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "tissue/scene/budget.h"

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace tissue::scene {

struct OptionCatalog::Impl {
  // The caller's thread only.
  struct Organ {
    bool offered = false;
    std::vector<int> options;                     // offered, table indices
    std::map<int, render::MethodSettings> built;  // lit's at once, the others as the worker ends them
    std::map<int, std::string> failed;            // could not be built, and why: never offered
  };
  std::vector<Organ> organs;
  Organ& organ(std::size_t i) {
    if (organs.size() <= i) organs.resize(i + 1);
    return organs[i];
  }

  // Shared with the worker, under `mutex`.
  struct Job {
    std::size_t organ = 0;
    std::shared_ptr<const OrganAssets> assets;  // a copy: the caller's organs may move in memory
    OrganTextures textures;                     // handles only
    MethodChoices choices;
    std::vector<std::pair<int, quality::QualityOption>> options;
  };
  struct Done {
    std::size_t organ = 0;
    int option = -1;
    Result<render::MethodSettings> settings;
  };
  std::mutex mutex;
  std::condition_variable wake, doneOne;
  std::deque<Job> jobs;  // a deque: appending keeps the front job's address while it is worked on
  std::vector<Done> done;
  bool stop = false;
  std::thread worker;

  ~Impl() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stop = true;
    }
    wake.notify_all();
    if (worker.joinable()) worker.join();
  }

  // One option at a time; the lock is held to take one and to hand it over, never during a fit.
  void work() {
#if defined(__linux__)
    // Idle priority: the fits run on cores the frame leaves idle. On the 2-core VM the demo's
    // 60 Hz frames ran at a median of 64 ms with the worker at normal priority against 34 ms
    // without it (llvmpipe's threads and the fits shared both cores). A refusal leaves the
    // normal priority (a container may forbid it); nothing else changes.
    sched_param idle{};
    (void)pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle);
#endif
    std::unique_lock<std::mutex> lock(mutex);
    std::size_t next = 0;  // within the front job
    for (;;) {
      wake.wait(lock, [this] { return stop || !jobs.empty(); });
      if (stop) return;
      Job& job = jobs.front();
      if (next >= job.options.size()) {
        jobs.pop_front();
        next = 0;
        continue;
      }
      lock.unlock();
      const auto& [index, option] = job.options[next];
      Done d{job.organ, index, methodOfOption(option, *job.assets, job.textures, job.choices)};
      lock.lock();
      done.push_back(std::move(d));
      doneOne.notify_all();
      ++next;
    }
  }
};

OptionCatalog::OptionCatalog() : m_impl(std::make_unique<Impl>()) {}
OptionCatalog::~OptionCatalog() = default;
OptionCatalog::OptionCatalog(OptionCatalog&&) noexcept = default;
OptionCatalog& OptionCatalog::operator=(OptionCatalog&&) noexcept = default;

void OptionCatalog::offer(std::size_t organ, const quality::QualityTable& table, const OrganAssets& assets,
                          const OrganTextures& textures, const MethodChoices& choices) {
  Impl::Organ& o = m_impl->organ(organ);
  if (o.offered) return;
  o.offered = true;
  o.options = offeredOptions(table, assets);
  Impl::Job job;
  job.organ = organ;
  for (int k : o.options) {
    if (o.built.count(k)) continue;  // kept from the host (keep)
    const quality::QualityOption& option = table.options[std::size_t(k)];
    if (option.method == "lit") {
      if (auto m = methodOfOption(option, assets, textures, choices))
        o.built.emplace(k, std::move(*m));
      else
        o.failed.emplace(k, m.error().message);
    } else {
      job.options.push_back({k, option});
    }
  }
  if (job.options.empty()) return;
  job.assets = std::make_shared<const OrganAssets>(assets);
  job.textures = textures;
  job.choices = choices;
  {
    std::lock_guard<std::mutex> lock(m_impl->mutex);
    m_impl->jobs.push_back(std::move(job));
    if (!m_impl->worker.joinable()) m_impl->worker = std::thread([impl = m_impl.get()] { impl->work(); });
  }
  m_impl->wake.notify_all();
}

bool OptionCatalog::offered(std::size_t organ) const {
  return organ < m_impl->organs.size() && m_impl->organs[organ].offered;
}

void OptionCatalog::collect() {
  std::vector<Impl::Done> done;
  {
    std::unique_lock<std::mutex> lock(m_impl->mutex, std::try_to_lock);
    if (!lock.owns_lock()) return;  // the worker is handing one over: next frame
    done.swap(m_impl->done);
  }
  for (Impl::Done& d : done) {
    Impl::Organ& o = m_impl->organ(d.organ);
    if (d.settings)
      o.built.emplace(d.option, std::move(*d.settings));
    else
      o.failed.emplace(d.option, d.settings.error().message);
  }
}

std::vector<int> OptionCatalog::ready(std::size_t organ) const {
  std::vector<int> out;
  if (organ >= m_impl->organs.size()) return out;
  const Impl::Organ& o = m_impl->organs[organ];
  for (int k : o.options)
    if (o.built.count(k)) out.push_back(k);
  if (out.empty())
    for (int k : o.options)
      if (!o.failed.count(k)) out.push_back(k);
  return out;
}

const render::MethodSettings* OptionCatalog::settings(std::size_t organ, int option) const {
  if (organ >= m_impl->organs.size()) return nullptr;
  const auto& built = m_impl->organs[organ].built;
  const auto it = built.find(option);
  return it == built.end() ? nullptr : &it->second;
}

Result<render::MethodSettings> OptionCatalog::chosen(std::size_t organ, int option,
                                                     const quality::QualityTable& table,
                                                     const OrganAssets& assets, const OrganTextures& textures,
                                                     const MethodChoices& choices) {
  if (const render::MethodSettings* built = settings(organ, option)) return *built;
  if (organ < m_impl->organs.size())  // the worker's error, kept: not fitted again
    if (const auto it = m_impl->organs[organ].failed.find(option); it != m_impl->organs[organ].failed.end())
      return Error{it->second};
  if (option < 0 || std::size_t(option) >= table.options.size())
    return Error{"budget: option " + std::to_string(option) + " is not in the quality table"};
  auto m = methodOfOption(table.options[std::size_t(option)], assets, textures, choices);
  if (!m) return m.error();
  keep(organ, option, *m);
  return m;
}

void OptionCatalog::keep(std::size_t organ, int option, render::MethodSettings settings) {
  m_impl->organ(organ).built.insert_or_assign(option, std::move(settings));
}

std::size_t OptionCatalog::pending() const {
  std::size_t n = 0;
  for (const Impl::Organ& o : m_impl->organs)
    for (int k : o.options)
      n += o.built.count(k) || o.failed.count(k) ? 0 : 1;
  return n;
}

void OptionCatalog::finish() {
  // The worker always moves on (each option ends built or failed), so this ends.
  while (pending() > 0) {
    {
      std::unique_lock<std::mutex> lock(m_impl->mutex);
      m_impl->doneOne.wait_for(lock, std::chrono::milliseconds(20), [this] { return !m_impl->done.empty(); });
    }
    collect();
  }
}

}  // namespace tissue::scene
