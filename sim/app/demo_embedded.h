#pragma once
/// \file
/// The main job's view of the embedding API: the scene a host embeds (tissue::scene::Scene),
/// with two organs of different methods and model matrices, poked by a host's instrument.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace tissue::sim_app {

/// The simulated liver (its scenario, separable SSS) and a static copy (turned, scaled 0.6 and
/// moved aside, texture-space diffusion) in one scene::Scene on its own headless context; the
/// instrument comes down 10 mm into the simulated one as a host would move it; writes
/// `outDir/frame_embedded_scene.png`. Returns what it did, or {"skipped": why}.
nlohmann::json renderEmbeddedScene(const std::filesystem::path& outDir, int width, int height);

}  // namespace tissue::sim_app
