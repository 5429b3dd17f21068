// One organ's render as tissue-sim render reports it (render_summary.h).
#include "tissue/studies/render_summary.h"

#include "loop_detail.h"

namespace tissue::studies {

std::string organRenderJson(const scene::OrganAssets& a, render::ShadingMethod method,
                            const scene::MethodChoices& c, const render::RenderTimings& t) {
  nlohmann::json out{
      {"method", render::shadingMethodName(method)},
      {"render_ms", t.totalCpuMs},
      {"passes", detail::passTimings(t)},
      {"upload_ms", t.uploadCpuMs},
      {"material", a.material.file.empty() ? "default" : a.material.file.string()},
      {"triangles", a.mesh.triangles.size()},
      {"uvs", a.atlas ? "automatic atlas (" + std::to_string(a.atlasCharts) + " charts)" : "the mesh's own"},
      {"base_color", a.baseColor ? a.material.textures.baseColor.string() : ""},
      {"normal_map", a.normalMap ? a.material.textures.normalMap.string() : ""}};
  switch (method) {
    case render::ShadingMethod::Lit:
      break;
    case render::ShadingMethod::Separable:
      out.update({{"kernel", c.kernel}, {"taps", c.taps}, {"rank", c.rank}});
      break;
    case render::ShadingMethod::TextureSpace:
      out.update({{"gaussians", c.gaussians},
                  {"map_size", c.mapSize},
                  {"cull", c.cull},
                  {"clip", c.clip},
                  {"depth_size", c.depthSize}});
      break;
    case render::ShadingMethod::RayMarch:
      out.update({{"adaptive", c.adaptive},
                  {c.adaptive ? "max_samples" : "march_samples",
                   c.adaptive ? render::RayMarchSettings{}.maxSamples : c.samples}});
      if (const auto* pass = t.find("ray-march")) out["pass_ms"] = pass->cpuMs;
      break;
    case render::ShadingMethod::Parallax:
      out.update({{"layer_depth_mm", c.parallaxDepthMm},
                  {"refractive_index", c.refractiveIndex.value_or(a.material.ior)},
                  {"lightmap_size", c.lightmap.size},
                  {"lightmap_reduction", c.lightmap.reduction},
                  {"blur_radius_mm", c.lightmap.blurRadiusMm},
                  {"blur_passes", c.lightmap.blurPasses},
                  {"cull", c.cull},
                  {"clip", c.clip}});
      break;
  }
  return out.dump();
}

}  // namespace tissue::studies
