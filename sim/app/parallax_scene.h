#pragma once
/// \file
/// What `tissue-sim render --method parallax` and `parallax-study` share: the organ and its
/// one-object scene (tissue/studies/parallax_scene.h, from data/materials/<mesh>.json when there
/// is one) on a headless context of the app's environment.

#include <filesystem>
#include <memory>
#include <optional>

#include "texture_space_setup.h"
#include "tissue/context/gl_context.h"
#include "tissue/render/renderer.h"
#include "tissue/studies/parallax_scene.h"

namespace tissue::sim_app {

using studies::ParallaxOptions;

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
