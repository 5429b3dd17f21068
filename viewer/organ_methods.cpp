// The viewer's shading methods for one organ, built from its material and textures.
#include "organ_methods.h"

#include "tissue/materials/method_materials.h"
#include "tissue/mesh/uv_atlas.h"

namespace tissue::viewer {

Result<std::vector<render::MethodSettings>> organMethods(const OrganAssets& organ,
                                                         const LayerTextures& layers) {
  std::vector<render::MethodSettings> methods{render::LitSettings{}};
  if (organ.material) {
    // The main job's choices: pre-integrated kernel with 17 taps (Freude eq. 5.17-5.18) and six
    // Gaussians fitted to the same dipole profile (d'Eon and Luebke).
    auto separable = materials::makeSeparableMaterial(*organ.material, "preintegrated", 17);
    if (!separable) return separable.error();
    methods.emplace_back(separable->settings);
    const auto& s = organ.surface;
    if (mesh::hasUsableUvs(s.uvs(), s.triangles(), s.positions().size())) {
      auto tsd = materials::makeTextureSpaceSettings(*organ.material, 6);
      if (!tsd) return tsd.error();
      methods.emplace_back(*tsd);
    }
  }
  if (layers.innerBase) {
    render::ParallaxSettings parallax;  // Norberg §2.2: one vessel layer 1.5 mm under the capsule
    parallax.layers = {render::ParallaxLayer{layers.innerBase, 1.5f, 1.0f}};
    parallax.opacityMap = layers.opacity;
    methods.emplace_back(parallax);
  }
  return methods;
}

Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name) {
  std::string offered;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string_view n = render::shadingMethodName(render::shadingMethod(methods[i]));
    if (n == name) return i;
    offered += (offered.empty() ? "" : ", ") + std::string(n);
  }
  return Error{
      "--method " + name + ": this organ offers " + offered +
      " (separable and texture-space need data/materials/<mesh>.json, parallax an inner_base texture)"};
}

}  // namespace tissue::viewer
