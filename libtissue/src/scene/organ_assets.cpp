// Loading an organ once: mesh (UV-atlas fallback), material file, textures (organ_assets.h).
#include "tissue/scene/organ_assets.h"

#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/uv_atlas.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::scene {
namespace {

/// The mesh with the atlas's render vertices (positions gathered from the geometric ones): the
/// geometric vertices, which a scenario moves, stay as they are.
SurfaceMesh withAtlas(const std::vector<Float3>& geometric, const mesh::UvAtlas& atlas) {
  SurfaceMesh out;
  for (std::uint32_t v : atlas.originalVertex)
    out.positions.push_back(geometric[v]);
  out.uvs = atlas.uvs;
  out.triangles = atlas.triangles;
  out.geometricIndex = atlas.originalVertex;
  out.geometricVertexCount = std::uint32_t(geometric.size());
  return out;
}

Result<std::optional<Image8>> readIfNamed(const std::filesystem::path& file) {
  if (file.empty()) return std::optional<Image8>();
  auto image = readImage(file, 4);
  if (!image) return Error{file.string() + ": " + image.error().message};
  return std::optional<Image8>(std::move(*image));
}

}  // namespace

Result<OrganAssets> loadOrganAssets(const OrganSource& source) {
  OrganAssets organ;
  // 1 the material: the file's, or the default organ.
  if (source.material.empty()) {
    organ.material = defaultMaterial();
  } else {
    auto material = readMaterialFile(source.material, source.materialOptions);
    if (!material) return material.error();
    organ.material = std::move(*material);
  }
  // 2 the mesh, with usable UVs: its own, else the atlas (computed once on the rest shape).
  auto loaded =
      mesh::loadMesh(source.mesh, {.requireUvs = !source.uvAtlasFallback, .scaleToMm = source.meshScaleToMm});
  if (!loaded) return loaded.error();
  organ.mesh = std::move(*loaded);
  SurfaceMesh& m = organ.mesh;
  if (!m.hasUvs() || !mesh::hasUsableUvs(m.uvs, m.triangles, m.positions.size())) {
    if (!source.uvAtlasFallback)
      return Error{source.mesh.string() +
                   ": its UVs overlap; texture-space diffusion needs unique UVs (allow the "
                   "automatic atlas, OrganSource::uvAtlasFallback)"};
    const std::vector<Float3> geometric = mesh::geometricPositionsOf(m);
    auto atlas = mesh::computeUvAtlas(geometric, mesh::geometricTrianglesOf(m));
    if (!atlas) return Error{source.mesh.string() + ": " + atlas.error().message};
    organ.atlasCharts = atlas->chartCount;
    m = withAtlas(geometric, *atlas);
    organ.atlas = true;
  }
  // 3 the textures the material names: all are painted on the file's own UVs, so none with the atlas.
  const MaterialTextures& t = organ.material.textures;
  const std::pair<const std::filesystem::path*, std::optional<Image8>*> textures[] = {
      {&t.baseColor, &organ.baseColor},
      {&t.normalMap, &organ.normalMap},
      {&t.opacity, &organ.opacity},
      {&t.innerBase, &organ.innerBase},
      {&t.subsurface, &organ.subsurfaceMap}};
  for (const auto& [file, slot] : textures) {
    if (organ.atlas) break;
    auto image = readIfNamed(*file);
    if (!image) return image.error();
    *slot = std::move(*image);
  }
  organ.uvPerMm = subsurface::uvPerMmOf(m.positions, m.uvs, m.triangles);
  organ.planes.sigma_t = firstLayerMinSigmaT(organ.material);
  organ.planes.epsilon = 0.01f;
  organ.bounds = boundsOf(m.positions);
  return organ;
}

}  // namespace tissue::scene
