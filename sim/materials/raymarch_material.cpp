// Layered material -> the renderer's ray-march settings.
#include "tissue/materials/raymarch_material.h"

#include "tissue/optics/schlick_phase.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::materials {

Result<RayMarchMaterial> loadRayMarchMaterial(const std::filesystem::path& materialFile,
                                              const std::filesystem::path& dataDir,
                                              const std::filesystem::path& mapFile,
                                              std::span<const Float3> positions, std::span<const Float2> uvs,
                                              std::span<const Triangle> triangles) {
  RayMarchMaterial m;
  auto stack = subsurface::loadLayerStack(materialFile, dataDir);
  if (!stack) return Error{stack.error().message + " (ray marching needs a data/ mesh with a material file)"};
  m.stack = std::move(*stack);
  auto map = readImage(mapFile, 4);
  if (!map) return Error{"subsurface map " + mapFile.string() + ": " + map.error().message};
  m.subsurfaceMap = std::move(*map);
  auto maps = subsurface::subsurfaceMapsFromImages(std::span<const Image8>(&m.subsurfaceMap, 1));
  if (!maps) return maps.error();
  m.stack.maps = std::move(*maps);
  m.uvPerMm = subsurface::uvPerMmOf(positions, uvs, triangles);
  return m;
}

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
