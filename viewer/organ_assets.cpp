// Loading the organ: scenario, mesh, the material's extinction and layers, textures.
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

/// Texture `name` of mesh `stem`: the generated version, else the committed one, else empty.
std::filesystem::path findTextureFile(const DataFolders& folders, const std::string& stem,
                                      const std::string& name) {
  for (const auto& dir : {folders.generated / "textures" / stem, folders.data / "textures" / stem})
    if (const auto path = dir / (name + ".png"); std::filesystem::exists(path)) return path;
  return {};
}

Result<std::optional<Image8>> findTexture(const DataFolders& folders, const std::string& stem,
                                          const std::string& name) {
  const auto path = findTextureFile(folders, stem, name);
  if (path.empty()) return std::optional<Image8>();
  auto image = readImage(path, 4);
  if (!image) return image.error();
  return std::optional<Image8>(std::move(*image));
}

}  // namespace

Result<OrganAssets> loadOrganAssets(const std::filesystem::path& scenarioFile, const DataFolders& folders) {
  if (!std::filesystem::exists(scenarioFile))
    return Error{scenarioFile.string() +
                 ": no such scenario file; give --scenario FILE (data/scenarios/*.json)"};
  auto scenario = scenario::loadScenario(scenarioFile, {.sharedMeshesDir = folders.shared / "meshes"});
  if (!scenario) return scenario.error();
  if (!scenario->instrument)
    return Error{scenarioFile.string() +
                 ": the scenario has no instrument; the viewer pokes with it (key "
                 "\"instrument\", docs/SCENARIOS.md)"};
  const auto meshFile = scenario->mesh;
  auto loaded = mesh::loadMesh(meshFile, {.requireUvs = true, .scaleToMm = float(scenario->meshScaleToMm)});
  if (!loaded) return loaded.error();
  const std::string stem = meshFile.stem().string();
  const auto materialFile = folders.data / "materials" / (stem + ".json");
  auto sigmaT = readFirstLayerSigmaT(materialFile, 1.5f);
  if (!sigmaT) return sigmaT.error();
  OrganAssets organ;
  organ.scenario = std::move(*scenario);
  organ.mesh = std::move(*loaded);
  organ.planes.sigma_t = *sigmaT;
  for (const auto& [name, slot] :
       {std::pair{"base_color", &organ.baseColor}, std::pair{"normal_map", &organ.normalMap},
        std::pair{"inner_base", &organ.innerBase}, std::pair{"opacity", &organ.opacity}}) {
    auto texture = findTexture(folders, stem, name);
    if (!texture) return texture.error();
    *slot = std::move(*texture);
  }
  if (std::filesystem::exists(materialFile)) {
    auto m = optics::loadTissueMaterial(materialFile);
    if (!m) return Error{materialFile.string() + ": " + m.error().message};
    organ.material = std::move(*m);
    // Ray marching needs the whole stack and its subsurface map; without the map it is not offered.
    if (const auto map = findTextureFile(folders, stem, "subsurface"); !map.empty()) {
      const auto& s = organ.mesh;
      auto rm =
          materials::loadRayMarchMaterial(materialFile, folders.data, map, s.positions, s.uvs, s.triangles);
      if (!rm) return rm.error();
      organ.rayMarch = std::move(*rm);
    }
  }
  return organ;
}

}  // namespace tissue::viewer
