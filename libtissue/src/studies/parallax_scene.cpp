// An organ ready for layered parallax and its one-object scene (parallax_scene.h).
#include "tissue/studies/parallax_scene.h"

#include <utility>

namespace tissue::studies {

Result<ParallaxOrgan> loadParallaxOrgan(const scene::OrganSource& source) {
  auto assets = scene::loadOrganAssets(source);
  if (!assets) return assets.error();
  ParallaxOrgan out;
  out.organ = tsdOrganOf(std::move(assets->mesh));
  out.organ.atlas = assets->atlas;
  out.organ.charts = assets->atlasCharts;
  // The layer textures live in the mesh's own UV space (loadOrganAssets drops them with the atlas).
  out.textured = !assets->atlas && assets->innerBase.has_value();
  if (out.textured) {
    out.baseColor = std::move(assets->baseColor);
    out.normalMap = std::move(assets->normalMap);
    out.opacity = std::move(assets->opacity);
    out.innerBase = std::move(assets->innerBase);
  }
  return out;
}

Result<render::Scene> makeParallaxScene(render::Renderer& renderer, const ParallaxOrgan& organ,
                                        const ParallaxOptions& options, float aspect) {
  auto mesh = renderer.createMesh(organ.organ.arrays());
  if (!mesh) return mesh.error();
  render::SceneObject object;
  object.mesh = *mesh;
  render::ParallaxSettings s = options.settings;
  s.layers = {render::ParallaxLayer{{}, options.layerDepthMm, 1.0f}};
  if (organ.textured) {
    for (auto [image, handle] :
         {std::pair{&organ.baseColor, &object.baseColor}, std::pair{&organ.normalMap, &object.normalMap},
          std::pair{&organ.opacity, &s.opacityMap}, std::pair{&organ.innerBase, &s.layers[0].base}}) {
      if (!image->has_value()) continue;
      auto texture = renderer.createTexture(**image);
      if (!texture) return texture.error();
      *handle = *texture;
    }
  }
  object.method = s;
  render::Scene scene;
  scene.camera = render::frameBoundingBox(organ.organ.lo, organ.organ.hi, aspect);
  scene.objects = {object};
  return scene;
}

}  // namespace tissue::studies
