// The layered-parallax commands' shared setup: organ, renderer, textures, one parallax object.
#include "parallax_scene.h"
#include "gl_environment.h"

#include <optional>

#include "organ_data.h"
#include "output.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/image.h"

namespace tissue::sim_app {

Result<ParallaxScene> loadParallaxScene(const std::filesystem::path& path, float scale, float aspect,
                                        int samples, const ParallaxOptions& options) {
  ParallaxScene out;
  auto organ = loadTsdOrgan(path, scale);
  if (!organ) return organ.error();
  out.organ = std::move(*organ);
  auto context = createAppContext({}, false);
  if (!context) return context.error();
  out.context = std::move(*context);
  auto renderer = render::Renderer::create(
      out.context->procAddressFunction(),
      {.shaders = shaderSettingsFromEnvironment(), .samples = samples, .gpuTimers = true});
  if (!renderer) return renderer.error();
  out.renderer = std::move(*renderer);
  auto mesh = out.renderer->createMesh(out.organ.arrays());
  if (!mesh) return mesh.error();
  render::SceneObject object;
  object.mesh = *mesh;
  render::ParallaxSettings s = options.settings;
  s.layers = {render::ParallaxLayer{{}, options.layerDepthMm, 1.0f}};
  // The project's layer textures (named by data/materials/<stem>.json, read by the scene module)
  // live in the mesh's own UV space: with an atlas they do not fit.
  std::optional<scene::MaterialFile> material;
  if (const auto file = materialFileFor(path); !out.organ.atlas && std::filesystem::exists(file)) {
    auto read = readDataMaterial(file);
    if (!read) return read.error();
    material = std::move(*read);
  }
  out.textured = material && !material->textures.innerBase.empty();
  if (out.textured) {
    const scene::MaterialTextures& t = material->textures;
    for (auto [file, handle] :
         {std::pair{&t.baseColor, &object.baseColor}, std::pair{&t.normalMap, &object.normalMap},
          std::pair{&t.opacity, &s.opacityMap}, std::pair{&t.innerBase, &s.layers[0].base}}) {
      if (file->empty()) continue;
      auto image = readImage(*file, 4);
      if (!image) return Error{file->string() + ": " + image.error().message};
      auto texture = out.renderer->createTexture(*image);
      if (!texture) return texture.error();
      *handle = *texture;
    }
  }
  object.method = s;
  out.scene.camera = render::frameBoundingBox(out.organ.lo, out.organ.hi, aspect);
  out.scene.objects = {object};
  return out;
}

}  // namespace tissue::sim_app
