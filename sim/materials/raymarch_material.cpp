// Layered material -> the renderer's ray-march settings.
#include "tissue/materials/raymarch_material.h"

#include "tissue/optics/schlick_phase.h"

namespace tissue::materials {

render::RayMarchSettings withRayMarchMaterial(render::RayMarchSettings march,
                                              const RayMarchMaterial& material, render::TextureHandle map) {
  march.layers.clear();
  for (const auto& l : material.stack.layers)
    march.layers.push_back({l.sigma_s, l.sigma_t, float(optics::schlickKFromG(l.g))});
  march.subsurfaceMaps = {map};
  march.depthScaleMm = material.stack.depthScaleMm;
  march.uvPerMm = material.uvPerMm;
  return march;
}

}  // namespace tissue::materials
