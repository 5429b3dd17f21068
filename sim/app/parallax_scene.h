#pragma once
/// \file
/// What `tissue-sim render --method parallax` and `parallax-study` share: a mesh made ready for
/// the layered-parallax method (unique UVs: its own, else the automatic atlas), a headless
/// renderer holding it with the project's layer textures (base colour, normal map, opacity, the
/// vessel network of inner_base.png; data/textures/<mesh>/), and a scene of one parallax object.

#include <filesystem>
#include <memory>
#include <optional>

#include "texture_space_setup.h"
#include "tissue/context/gl_context.h"
#include "tissue/render/renderer.h"

namespace tissue::sim_app {

/// The parallax settings a command may change (defaults: ParallaxSettings').
struct ParallaxOptions {
  float layerDepthMm = 1.5f;  ///< mm, the one inner layer's depth
  render::ParallaxSettings settings;
};

/// A renderer with one parallax object. The context outlives the renderer (member order).
struct ParallaxScene {
  std::unique_ptr<context::GlContext> context;
  std::optional<render::Renderer> renderer;
  TsdOrgan organ;
  render::Scene scene;    ///< camera framing the mesh, no lights yet
  bool textured = false;  ///< the mesh's own UVs and data textures (false: atlas, default colours)
};

/// Loads `path` (mm per file unit `scale`), creates a headless context and renderer (MSAA
/// `samples`) and the object; the camera frames the mesh for width / height = `aspect`.
Result<ParallaxScene> loadParallaxScene(const std::filesystem::path& path, float scale, float aspect,
                                        int samples, const ParallaxOptions& options);

}  // namespace tissue::sim_app
