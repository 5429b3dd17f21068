#pragma once
/// \file
/// The quality table options each organ may be drawn with under a frame budget (issue 16), and
/// their renderer settings, built off the frame path. An option's settings are a CPU fit of the
/// material's optics: a separable kernel 9-16 ms, texture space's Gaussians 32-104 ms (the budget
/// bench's liver, 2-core VM). Built when the controller first chose the option, that fit stalled
/// the frame that switched to it, and under a tight budget each such frame broke it. The catalog
/// builds lit's settings at once (a uniform, no fit) and the others on one worker thread, and
/// offers the controller only the built ones (ready), so that no frame waits for a fit. Used by
/// Scene and by the viewer. GL-free: settings hold texture handles, no call is made.

#include <cstddef>
#include <memory>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/quality/quality_table.h"
#include "tissue/render/renderer.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::scene {

class OptionCatalog {
 public:
  OptionCatalog();
  ~OptionCatalog();  ///< stops after the fit under way (at most ~0.1 s) and joins the worker
  OptionCatalog(OptionCatalog&&) noexcept;
  OptionCatalog& operator=(OptionCatalog&&) noexcept;

  /// Organ `organ`'s offered options (scene::offeredOptions) from `table`: lit's built now, the
  /// others queued for the worker (it copies `assets`: the caller's may move). Once per organ;
  /// later calls for it do nothing.
  void offer(std::size_t organ, const quality::QualityTable& table, const OrganAssets& assets,
             const OrganTextures& textures, const MethodChoices& choices);
  bool offered(std::size_t organ) const;
  /// Takes what the worker finished since the last call (never waits for a fit).
  void collect();
  /// The organ's offered options whose settings are built: the controller's choice
  /// (quality::ObjectView::allowed). Never empty once offered while any is built; with none
  /// built yet (no lit offered), the offered ones.
  std::vector<int> ready(std::size_t organ) const;
  /// The built settings of `option` for the organ, or nullptr.
  const render::MethodSettings* settings(std::size_t organ, int option) const;
  /// The settings of the controller's choice `option` for the organ: the built ones; the error
  /// the worker met building it; or (an option offered before any was built: a table without
  /// lit) built now, once, and kept.
  Result<render::MethodSettings> chosen(std::size_t organ, int option, const quality::QualityTable& table,
                                        const OrganAssets& assets, const OrganTextures& textures,
                                        const MethodChoices& choices);
  /// Keeps settings the caller built (a host's setMethodOption) for the organ's `option`.
  void keep(std::size_t organ, int option, render::MethodSettings settings);
  /// Offered options neither built nor failed yet (0 once the worker is done).
  std::size_t pending() const;
  /// Waits on the calling thread until nothing is pending (a host's loading screen).
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::scene
