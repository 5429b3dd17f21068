// Every method's settings for one organ, from its material file and textures (organ_methods.h).
#include "tissue/scene/organ_methods.h"

#include "tissue/materials/method_materials.h"
#include "tissue/mesh/uv_atlas.h"
#include "tissue/optics/schlick_phase.h"

namespace tissue::scene {
namespace {

std::string materialName(const OrganAssets& organ) {
  return organ.material.file.empty() ? "the default organ material" : organ.material.file.string();
}

}  // namespace

Result<OrganTextures> uploadOrganTextures(render::Renderer& renderer, const OrganAssets& organ) {
  OrganTextures t;
  // The colour comes from the optics (material_file.h): the base colour is the first layer's
  // albedo (the painted texture at most a luminance detail, MaterialFile::baseColorDetail),
  // the parallax inner layer the albedo of the layer at the parallax depth under each texel.
  const std::optional<Image8> base =
      opticalBaseColor(organ.material, organ.baseColor ? &*organ.baseColor : nullptr);
  std::optional<Image8> inner = organ.innerBase;
  if (organ.innerBase && organ.subsurfaceMap)
    inner = opticalLayerImage(organ.material, *organ.subsurfaceMap, MethodChoices{}.parallaxDepthMm,
                              &*organ.innerBase);
  const std::pair<const std::optional<Image8>*, render::TextureHandle*> colour[] = {
      {&base, &t.baseColor},
      {&organ.normalMap, &t.normalMap},
      {&organ.opacity, &t.opacity},
      {&inner, &t.innerBase}};
  for (const auto& [image, handle] : colour) {
    if (!*image) continue;
    auto uploaded = renderer.createTexture(**image);
    if (!uploaded) return destroyOrganTextures(renderer, t), uploaded.error();
    *handle = *uploaded;
  }
  if (organ.subsurfaceMap) {
    // Depths, not colours: bilinear without mip-maps (a mip level would average boundaries).
    auto map = renderer.createTexture(*organ.subsurfaceMap, render::TextureEncoding::LinearData);
    if (!map) return destroyOrganTextures(renderer, t), map.error();
    t.subsurfaceMap = *map;
  }
  return t;
}

void destroyOrganTextures(render::Renderer& renderer, OrganTextures& textures) {
  for (render::TextureHandle* h : {&textures.baseColor, &textures.normalMap, &textures.opacity,
                                   &textures.innerBase, &textures.subsurfaceMap}) {
    if (*h) renderer.destroyTexture(*h);
    *h = {};
  }
}

std::vector<render::ShadingMethod> offeredMethods(const OrganAssets& organ) {
  using render::ShadingMethod;
  std::vector<ShadingMethod> methods{ShadingMethod::Lit, ShadingMethod::Separable};
  const SurfaceMesh& m = organ.mesh;
  if (mesh::hasUsableUvs(m.uvs, m.triangles, m.positions.size()))
    methods.push_back(ShadingMethod::TextureSpace);
  if (organ.subsurfaceMap) methods.push_back(ShadingMethod::RayMarch);
  if (organ.innerBase) methods.push_back(ShadingMethod::Parallax);
  return methods;
}

Result<render::MethodSettings> organMethod(render::ShadingMethod method, const OrganAssets& organ,
                                           const OrganTextures& textures, const MethodChoices& choices) {
  using render::ShadingMethod;
  switch (method) {
    case ShadingMethod::Lit:
      return render::MethodSettings{
          render::LitSettings{.wrap = choices.litWrapFromOptics ? opticalWrap(organ) : choices.litWrap}};
    case ShadingMethod::Separable: {
      // The first layer's dipole profile as a kernel (Freude eq. 5.10; pre-integrated by default,
      // eq. 5.17-5.18), with its transmittance table (Jimenez et al. 2010).
      auto separable = materials::makeSeparableMaterial(opticalMaterial(organ.material), choices.kernel,
                                                        choices.taps, choices.rank);
      if (!separable) return Error{materialName(organ) + ": " + separable.error().message};
      return render::MethodSettings{separable->settings};
    }
    case ShadingMethod::TextureSpace: {
      const SurfaceMesh& m = organ.mesh;
      if (!mesh::hasUsableUvs(m.uvs, m.triangles, m.positions.size()))
        return Error{"texture-space diffusion needs unique UVs; load the organ with the UV-atlas fallback"};
      auto tsd = materials::makeTextureSpaceSettings(opticalMaterial(organ.material), choices.gaussians);
      if (!tsd) return Error{materialName(organ) + ": " + tsd.error().message};
      tsd->mapSize = choices.mapSize;
      tsd->cull = choices.cull, tsd->clip = choices.clip, tsd->depthSize = choices.depthSize;
      return render::MethodSettings{*tsd};
    }
    case ShadingMethod::RayMarch: {
      if (!organ.subsurfaceMap || !textures.subsurfaceMap)
        return Error{"ray marching needs a subsurface map: " + materialName(organ) +
                     " must name textures.subsurface (docs/DATA.md)"};
      auto stack = layerStack(organ.material, *organ.subsurfaceMap);
      if (!stack) return stack.error();
      // François et al. 2006 Algorithm 2 through the whole stack; Schlick's k from each layer's g;
      // each layer's multiple-scattered albedo and transport coefficient from the optics
      // (optics::semiInfiniteReflectance); the outer surface's Fresnel and specular (§3).
      render::RayMarchSettings march;
      march.samples = choices.samples;
      march.adaptive = choices.adaptive;
      for (std::size_t i = 0; i < stack->layers.size(); ++i) {
        const auto& l = stack->layers[i];
        const LayerReflectance r = layerReflectance(organ.material, i);
        march.layers.push_back(
            {l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g)), r.multiple, r.sigmaTr});
      }
      march.ior = organ.material.ior;
      march.specular = true;
      // The lights' radiance is E / pi (the lit method's convention): pi gives the march E.
      march.radianceScale = 3.14159265f;
      march.subsurfaceMaps = {textures.subsurfaceMap};
      march.depthScaleMm = stack->depthScaleMm;
      march.uvPerMm = organ.uvPerMm;
      return render::MethodSettings{march};
    }
    case ShadingMethod::Parallax: {
      if (!textures.innerBase)
        return Error{"layered parallax needs an inner layer: " + materialName(organ) +
                     " must name textures.inner_base (docs/DATA.md)"};
      // Norberg 2010 §2.2: one inner layer (the vessels) under the outer layer's opacity; both
      // layers' colours are the optics' (uploadOrganTextures).
      render::ParallaxSettings parallax;
      parallax.layers = {render::ParallaxLayer{textures.innerBase, choices.parallaxDepthMm, 1.0f}};
      parallax.opacityMap = textures.opacity;
      parallax.refractiveIndex = choices.refractiveIndex.value_or(organ.material.ior);
      parallax.lightmap = choices.lightmap;
      parallax.lightmap.cull = choices.cull, parallax.lightmap.clip = choices.clip;
      return render::MethodSettings{parallax};
    }
  }
  return Error{"unknown shading method"};
}

Result<reference::RadialProfile> separableTruth(const OrganAssets& organ, const MethodChoices& choices) {
  auto separable = materials::makeSeparableMaterial(opticalMaterial(organ.material), choices.kernel,
                                                    choices.taps, choices.rank);
  if (!separable) return Error{materialName(organ) + ": " + separable.error().message};
  return std::move(separable->truth);
}

float opticalWrap(const OrganAssets& organ) {
  if (organ.material.layers.empty()) return 0.0f;
  const Float3 tr = layerReflectance(organ.material, 0).sigmaTr;
  const double sigma = std::min({double(tr.x), double(tr.y), double(tr.z)});
  double area = 0.0;
  const auto& p = organ.mesh.positions;
  for (const Triangle& t : organ.mesh.triangles)
    area += 0.5 * double(length(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]])));
  if (!(sigma > 0.0) || !(area > 0.0)) return 0.0f;
  const double radiusMm = std::sqrt(area / (4.0 * 3.14159265358979));
  return float(std::clamp(1.0 / (sigma * radiusMm), 0.0, 0.5));
}

render::Material surfaceMaterialOf(const OrganAssets& organ, Float3 ambient) {
  render::Material m;
  m.specular = specularF0(organ.material);
  m.ambient = ambient;
  return m;
}

render::SceneObject organObject(render::MeshHandle mesh, const OrganTextures& textures,
                                render::MethodSettings method, const render::Material& surface) {
  render::SceneObject o;
  o.mesh = mesh;
  o.baseColor = textures.baseColor;
  o.normalMap = textures.normalMap;
  o.material = surface;
  o.method = std::move(method);
  return o;
}

Result<render::ShadingMethod> parseShadingMethod(std::string_view name) {
  using render::ShadingMethod;
  for (ShadingMethod m : {ShadingMethod::Lit, ShadingMethod::Separable, ShadingMethod::TextureSpace,
                          ShadingMethod::RayMarch, ShadingMethod::Parallax})
    if (render::shadingMethodName(m) == name) return m;
  if (name == "raymarch") return ShadingMethod::RayMarch;  // tissue-sim's older spelling
  return Error{"method '" + std::string(name) +
               "': use lit, separable, texture-space, ray-march or parallax"};
}

}  // namespace tissue::scene
