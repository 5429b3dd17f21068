#pragma once
/// \file
/// tissue-sim's side of the scene module's organ layer (tissue/scene/material_file.h,
/// organ_assets.h, scene.h): where the project's material files and textures are (data/materials/,
/// the build's generated 1024^2 textures before the committed small ones). The reading itself is
/// the scene module's, the one reader of data/materials/*.json.

#include <filesystem>
#include <string>

#include "tissue/core/result.h"
#include "tissue/materials/method_materials.h"  // for the files that include this one
#include "tissue/optics/materials.h"
#include "tissue/scene/material_file.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/scene.h"

namespace tissue::sim_app {

/// The texture roots of the project's material files: the generated data dir, then data/.
scene::MaterialFileOptions dataMaterialOptions();

/// data/materials/<mesh stem>.json for a mesh file.
std::filesystem::path materialFileFor(const std::filesystem::path& meshFile);

/// Reads `file` with dataMaterialOptions(); errors name the file (scene::readMaterialFile).
Result<scene::MaterialFile> readDataMaterial(const std::filesystem::path& file);

/// An organ from `meshFile` (mm per unit `scaleToMm`) and its data/materials/<stem>.json, with
/// the scene module's UV-atlas fallback.
scene::OrganSource organSourceFor(const std::filesystem::path& meshFile, float scaleToMm = 1.0f);

/// The data organ `name`: data/meshes/<name>.obj with its material file (organSourceFor).
scene::OrganSource dataOrganNamed(const std::string& name);

/// A scene's settings for the project's data: data/materials/ (an organ's material by its mesh's
/// name), the shared meshes, and the environment's shaders and headless context.
scene::SceneSettings dataSceneSettings();

}  // namespace tissue::sim_app
