// The layered-parallax commands' shared setup: the library's organ and scene on the app's context.
#include "parallax_scene.h"

#include "gl_environment.h"
#include "organ_data.h"
#include "tissue/context/headless_context.h"

namespace tissue::sim_app {

Result<ParallaxScene> loadParallaxScene(const std::filesystem::path& path, float scale, float aspect,
                                        int samples, const ParallaxOptions& options) {
  // data/materials/<stem>.json when there is one (else the default organ, untextured).
  scene::OrganSource source = organSourceFor(path, scale);
  if (!std::filesystem::exists(source.material)) source.material.clear();
  auto organ = studies::loadParallaxOrgan(source);
  if (!organ) return organ.error();
  ParallaxScene out;
  auto context = createAppContext({}, false);
  if (!context) return context.error();
  out.context = std::move(*context);
  auto renderer = render::Renderer::create(
      out.context->procAddressFunction(),
      {.shaders = shaderSettingsFromEnvironment(), .samples = samples, .gpuTimers = true});
  if (!renderer) return renderer.error();
  out.renderer = std::move(*renderer);
  auto scene = studies::makeParallaxScene(*out.renderer, *organ, options, aspect);
  if (!scene) return scene.error();
  out.scene = std::move(*scene);
  out.textured = organ->textured;
  out.organ = std::move(organ->organ);
  return out;
}

}  // namespace tissue::sim_app
