#pragma once
/// \file
/// tissue-sim's ray-march renders: the organ (tissue::studies::RayMarchScene, from the project's
/// data/ folders) rendered on a headless context of the app's environment into PNGs. The scene,
/// its renderer and the CPU model's views are the library's (tissue/studies/raymarch_scene.h).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"
#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/studies/raymarch_scene.h"

namespace tissue::sim_app {

/// `tissue-sim render --method raymarch`: the whole organ of data/ mesh `meshFile`; prints the
/// result like every command and returns the exit code.
int runRayMarchRender(const std::string& meshFile, const std::string& png, int width, int height, int samples,
                      bool adaptive, const GlobalOptions& global);

/// The demo's ray-marched render of its poked organ (`organ`: its material and subsurface map):
/// the whole organ and a close-up of the poke, adaptive quality, into `outDir`.
/// Returns the report entry (images written, or why they were skipped).
nlohmann::json renderPokedOrganRayMarch(const mesh::DeformableSurface& surface,
                                        const scene::OrganAssets& organ, const std::filesystem::path& outDir,
                                        int width, int height);

}  // namespace tissue::sim_app
