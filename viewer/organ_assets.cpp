// Loading the organ: mesh, the material's extinction, textures.
#include "organ_assets.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "tissue/core/atomic_file.h"
#include "tissue/mesh/load_mesh.h"

namespace tissue::viewer {
namespace {

/// The smallest RGB extinction (mm^-1) of the first layer of `materialFile`; `fallback` when
/// there is no such file (a mesh from outside the project).
Result<float> readFirstLayerSigmaT(const std::filesystem::path& materialFile, float fallback) {
  if (!std::filesystem::exists(materialFile)) return fallback;
  auto text = readTextFile(materialFile);
  if (!text) return text.error();
  try {
    const auto json = nlohmann::json::parse(*text);
    const auto sigmaT = json.at("layers").at(0).at("sigma_t").get<std::vector<float>>();
    if (sigmaT.size() != 3 || *std::min_element(sigmaT.begin(), sigmaT.end()) <= 0.0f)
      return Error{materialFile.string() + ": layers[0].sigma_t must be 3 positive numbers (mm^-1)"};
    return *std::min_element(sigmaT.begin(), sigmaT.end());
  } catch (const nlohmann::json::exception& e) {
    return Error{materialFile.string() + ": " + e.what() + "; see docs/DATA.md for the schema"};
  }
}

/// Texture `name` of mesh `stem`: the generated version, else the committed one, else none.
Result<std::optional<Image8>> findTexture(const DataFolders& folders, const std::string& stem,
                                          const std::string& name) {
  for (const auto& dir : {folders.generated / "textures" / stem, folders.data / "textures" / stem}) {
    const auto path = dir / (name + ".png");
    if (!std::filesystem::exists(path)) continue;
    auto image = readImage(path, 4);
    if (!image) return image.error();
    return std::optional<Image8>(std::move(*image));
  }
  return std::optional<Image8>();
}

}  // namespace

Result<OrganAssets> loadOrganAssets(const std::filesystem::path& meshFile, const DataFolders& folders) {
  mesh::LoadOptions options;
  options.requireUvs = true;
  auto loaded = mesh::loadMesh(meshFile, options);
  if (!loaded) return loaded.error();
  const std::string stem = meshFile.stem().string();
  auto sigmaT = readFirstLayerSigmaT(folders.data / "materials" / (stem + ".json"), 1.5f);
  if (!sigmaT) return sigmaT.error();
  mesh::PlaneFitSettings planes;
  planes.sigma_t = *sigmaT;
  auto surface = mesh::DeformableSurface::create(std::move(*loaded), planes);
  if (!surface) return Error{meshFile.string() + ": " + surface.error().message};
  auto baseColor = findTexture(folders, stem, "base_color");
  if (!baseColor) return baseColor.error();
  auto normalMap = findTexture(folders, stem, "normal_map");
  if (!normalMap) return normalMap.error();
  auto innerBase = findTexture(folders, stem, "inner_base");
  if (!innerBase) return innerBase.error();
  auto opacity = findTexture(folders, stem, "opacity");
  if (!opacity) return opacity.error();
  std::optional<optics::ScatteringMaterial> material;
  if (const auto file = folders.data / "materials" / (stem + ".json"); std::filesystem::exists(file)) {
    auto m = optics::loadTissueMaterial(file);
    if (!m) return Error{file.string() + ": " + m.error().message};
    material = std::move(*m);
  }
  return OrganAssets{std::move(*surface),
                     std::move(*baseColor),
                     std::move(*normalMap),
                     std::move(*innerBase),
                     std::move(*opacity),
                     std::move(material),
                     *sigmaT};
}

}  // namespace tissue::viewer
