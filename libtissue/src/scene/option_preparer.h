#pragma once
// Builds the renderer settings of an organ's quality-table options off the frame path (Scene's
// budget, issue 16). An option's settings are a CPU fit of the material's optics: the separable
// kernels 9-16 ms each, texture space's Gaussians 32-104 ms (measured on the budget bench's
// liver, 2-core VM); built when the controller first chose an option, they stalled the frame that
// switched to it by that much, and under a tight budget each such frame broke it. One worker
// thread builds every organ's offered options in turn; the controller is offered only the ready
// ones (Scene's applyBudget), so a host's frame never waits for a fit. Internal to tissue_scene.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/quality/quality_table.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::scene::detail {

/// One organ's options to build: a snapshot of what methodOfOption reads (the organ's assets are
/// copied: the scene's organs may move in memory while the worker reads them).
struct PrepareJob {
  std::size_t organ = 0;
  std::shared_ptr<const OrganAssets> assets;
  OrganTextures textures;  // handles only: no GL call builds settings
  MethodChoices choices;
  std::vector<std::pair<int, quality::QualityOption>> options;  // table index, option
};

/// A finished option: its settings, or why it cannot be built (the option is then never offered).
struct PreparedOption {
  std::size_t organ = 0;
  int option = -1;
  Result<render::MethodSettings> settings;
};

class OptionPreparer {
 public:
  OptionPreparer() = default;
  OptionPreparer(const OptionPreparer&) = delete;
  OptionPreparer& operator=(const OptionPreparer&) = delete;
  /// Stops after the option being built (at most one fit, ~0.1 s) and joins.
  ~OptionPreparer();

  /// Queues `job`; starts the worker on the first.
  void add(PrepareJob job);
  /// The options finished since the last call (non-blocking: never waits for a fit).
  std::vector<PreparedOption> collect();
  /// No job queued or running.
  bool idle();

 private:
  void work();

  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::deque<PrepareJob> m_jobs;  // queued, in order (a deque: adding keeps the front's address)
  std::vector<PreparedOption> m_done;
  bool m_busy = false;  // the worker is building an option
  bool m_stop = false;
  std::thread m_worker;
};

}  // namespace tissue::scene::detail
