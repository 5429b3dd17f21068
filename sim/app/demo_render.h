#pragma once
/// \file
/// The demo's method renders of its poked organ: one static organ of a scene::Scene (4x MSAA),
/// shaped by Scene::setPositions and switched between the methods at run time (Scene::setMethod;
/// every method's settings are the scene module's, organMethod with the main job's choices).

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tissue/mesh/deformable_surface.h"
#include "tissue/scene/scene.h"

namespace tissue::sim_app {

/// Renders organ 0 of `scene` with screen-space separable SSS or, with `textureSpace`, with
/// texture-space diffusion (d'Eon et al. 2007 with the culled, depth-sized and clipped maps of
/// Jimenez et al. 2008), lit by a shadow-casting lamp; writes `png` and reports the pass
/// timings and the image RMS of the subsurface diffuse against the CPU reference (the exact
/// convolution of the same frame's pre-blur diffuse); {"skipped": why} when it cannot.
nlohmann::json renderSubsurface(scene::Scene& scene, const std::filesystem::path& png, int width, int height,
                                bool textureSpace);

/// Renders organ 0 with layered parallax (Oat 2006; Norberg §2.2: the vessel network 1.5 mm
/// under the outer layer's opacity); writes `png` and reports the pass timings.
nlohmann::json renderParallax(scene::Scene& scene, const std::filesystem::path& png, int width, int height);

/// Frames organ 0 of `scene` (its shape `surface`) as the ray-march studies do
/// (studies::rayMarchSceneFor: the whole organ, or with `closeUp` 40 mm around the poke site)
/// and lights it with their key and back lights, which stay; frameOrgans() frames it again.
Result<void> frameForRayMarch(scene::Scene& scene, const mesh::DeformableSurface& surface, float aspect,
                              bool closeUp);

/// Renders organ 0 ray-marched (François et al. 2006, adaptive quality), the whole organ and a
/// close-up of the poke site of `surface` (its shape), with the ray-march studies' key and back
/// lights (studies::rayMarchSceneFor), into `outDir`/frame_poked_raymarch{,_closeup}.png. The
/// scene's lights stay the ray march's. Returns the images' entries, or {"skipped": why}.
nlohmann::json renderRayMarch(scene::Scene& scene, const mesh::DeformableSurface& surface,
                              const std::filesystem::path& outDir, int width, int height);

}  // namespace tissue::sim_app
