#pragma once
// Private to tissue::studies: the main job's method renders of its poked organ (one static organ
// of a scene::Scene, 4x MSAA, shaped by Scene::setPositions and switched between the methods at
// run time; every method's settings are the scene module's organMethod with the main job's
// choices), and the scene a host embeds. Each returns its report entry, or {"skipped": why}.

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tissue/mesh/deformable_surface.h"
#include "tissue/scene/scene.h"

namespace tissue::studies::detail {

/// Renders organ 0 of `scene` with screen-space separable SSS or, with `textureSpace`, with
/// texture-space diffusion (d'Eon et al. 2007 with the culled, depth-sized and clipped maps of
/// Jimenez et al. 2008), lit by a shadow-casting lamp; writes `png` and reports the pass
/// timings and the image RMS of the subsurface diffuse against the CPU reference (the exact
/// convolution of the same frame's pre-blur diffuse).
nlohmann::json renderSubsurface(scene::Scene& scene, const std::filesystem::path& png, int width, int height,
                                bool textureSpace);

/// Renders organ 0 with layered parallax (Oat 2006; Norberg §2.2: the vessel network 1.5 mm
/// under the outer layer's opacity); writes `png` and reports the pass timings.
nlohmann::json renderParallax(scene::Scene& scene, const std::filesystem::path& png, int width, int height);

/// Renders organ 0 ray-marched (François et al. 2006, adaptive quality), the whole organ and a
/// close-up of the poke site of `surface` (its shape), with the ray-march studies' key and back
/// lights, into `outDir`/frame_poked_raymarch{,_closeup}.png. The scene's lights stay the ray
/// march's. Returns the images' entries.
nlohmann::json renderRayMarch(scene::Scene& scene, const mesh::DeformableSurface& surface,
                              const std::filesystem::path& outDir, int width, int height);

/// The simulated liver (its scenario, separable SSS) and a static copy (turned, scaled 0.6 and
/// moved aside, texture-space diffusion) in one scene::Scene on its own headless context
/// (`settings`); the instrument comes down 10 mm into the simulated one as a host would move it;
/// writes `outDir/frame_embedded_scene.png`; then 45 frames under each of two frame budgets (60 Hz,
/// 1 s) with the quality controller choosing the organs' methods, each budget's last frame
/// `frame_embedded_budget_<ms>ms.png` and its choices in the entry's `budgets`. `dataDir`: the
/// project's data/.
nlohmann::json renderEmbeddedScene(const scene::SceneSettings& settings, const std::filesystem::path& dataDir,
                                   const std::filesystem::path& outDir, int width, int height);

}  // namespace tissue::studies::detail
