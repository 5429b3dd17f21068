#pragma once
/// \file
/// The demo's rendering: a headless context (EGL, falling back to OSMesa) and the renderer
/// core, created on first use; the organ is uploaded once and then updated in place, its textures
/// and every method's settings from the scene module (scene::uploadOrganTextures, organMethod).

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "organ_data.h"
#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_loop.h"

namespace tissue::sim_app {

/// Renders a deformable surface with its textures into PNG files.
class DemoRenderer {
 public:
  DemoRenderer(int width, int height);
  ~DemoRenderer();
  DemoRenderer(const DemoRenderer&) = delete;
  DemoRenderer& operator=(const DemoRenderer&) = delete;

  /// Sets up the context, the renderer, the organ's textures and a camera framing `surface`'s
  /// rest shape, once (later calls only make the context current).
  Result<void> prepare(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ);
  /// Attaches `loop` to the renderer (its own mesh, drawn lit like the organ) and returns the
  /// render request that draws it offscreen into `image` at `width` x `height` pixels.
  Result<scene::RenderRequest> attachLoop(scene::OrganLoop& loop, const scene::OrganAssets& organ, int width,
                                          int height, Image8* image);
  /// Makes the renderer's context current (before a loop frame that renders).
  Result<void> makeCurrent();
  /// Renders the surface as it is now and writes `png` atomically.
  Result<void> render(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ,
                      const std::filesystem::path& png);
  /// Renders the surface as it is now with screen-space separable SSS (the material's dipole
  /// profile, pre-integrated kernel, 17 taps) or, with `textureSpace`, with texture-space
  /// diffusion (d'Eon et al. 2007 with the culled, depth-sized and clipped maps of Jimenez et al.
  /// 2008; six Gaussians fitted to the same profile, the organ's own UVs); writes `png` and
  /// reports the pass timings and the image RMS of the subsurface diffuse against the CPU
  /// reference (the exact convolution of the same frame); {"skipped": why} when it cannot.
  nlohmann::json renderSubsurface(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ,
                                  const std::filesystem::path& png, bool textureSpace);
  /// Renders the surface as it is now with layered parallax (Oat 2006; Norberg §2.2): the
  /// organ's base colour and normal map as the outer layer, its opacity map, and the vessel
  /// network (inner_base.png) 1.5 mm below; writes `png` and reports the pass timings.
  nlohmann::json renderParallax(const mesh::DeformableSurface& surface, const scene::OrganAssets& organ,
                                const std::filesystem::path& png);
  /// GL context and renderer strings, and the last frame's timings (ms).
  nlohmann::json info() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace tissue::sim_app
