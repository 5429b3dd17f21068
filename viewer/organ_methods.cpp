// The viewer's shading methods for one organ, built from its material and textures.
#include "organ_methods.h"

#include "tissue/materials/method_materials.h"
#include "tissue/mesh/uv_atlas.h"

namespace tissue::viewer {

Result<std::vector<render::MethodSettings>> organMethods(const OrganAssets& organ,
                                                         const LayerTextures& layers,
                                                         const MethodChoices& choices) {
  std::vector<render::MethodSettings> methods{render::LitSettings{}};
  if (organ.material) {
    // The main job's defaults: pre-integrated kernel with 17 taps (Freude eq. 5.17-5.18) and six
    // Gaussians fitted to the same dipole profile (d'Eon and Luebke).
    auto separable = materials::makeSeparableMaterial(*organ.material, choices.kernel, choices.taps);
    if (!separable) return separable.error();
    methods.emplace_back(separable->settings);
    const auto& s = organ.mesh;
    if (mesh::hasUsableUvs(s.uvs, s.triangles, s.positions.size())) {
      auto tsd = materials::makeTextureSpaceSettings(*organ.material, choices.gaussians);
      if (!tsd) return tsd.error();
      methods.emplace_back(*tsd);
    }
  }
  if (organ.rayMarch && layers.subsurfaceMap) {
    // Fixed samples (the panel's count), jittered: François et al. 2006 Algorithm 2 per pixel.
    render::RayMarchSettings march;
    march.samples = choices.samples;
    methods.emplace_back(materials::withRayMarchMaterial(march, *organ.rayMarch, layers.subsurfaceMap));
  }
  if (layers.innerBase) {
    render::ParallaxSettings parallax;  // Norberg §2.2: one vessel layer 1.5 mm under the capsule
    parallax.layers = {render::ParallaxLayer{layers.innerBase, 1.5f, 1.0f}};
    parallax.opacityMap = layers.opacity;
    methods.emplace_back(parallax);
  }
  return methods;
}

std::string methodName(const render::MethodSettings& method) {
  return std::string(render::shadingMethodName(render::shadingMethod(method)));
}

Result<std::size_t> findMethod(const std::vector<render::MethodSettings>& methods, const std::string& name) {
  std::string offered;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string n = methodName(methods[i]);
    if (n == name) return i;
    offered += (offered.empty() ? "" : ", ") + n;
  }
  return Error{"method " + name + ": this organ offers " + offered +
               " (separable and texture-space need data/materials/<mesh>.json, ray-march also its "
               "subsurface map, parallax an inner_base texture)"};
}

}  // namespace tissue::viewer
