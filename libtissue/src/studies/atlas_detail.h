#pragma once
// Private to tissue::studies: the atlas's truth cache (a hash of everything a truth image depends
// on, and the image on disk) and its report.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tissue/core/surface_mesh.h"
#include "tissue/render/scene.h"
#include "tissue/studies/atlas.h"
#include "tissue/truth/material.h"
#include "tissue/truth/path_tracer.h"

namespace tissue::studies::detail {

/// The laparoscope's light: a shadowed point lamp at the light port beside the lens, `rightMm`,
/// `upMm` and `forwardMm` from `camera`'s eye along its axes (mm). Laparoscopes carry their light
/// down the scope, so every view a trainee sees is lit from about where it is seen from; the
/// budget bench and the atlas's laparoscope frames share this lamp so that the table's errors are
/// measured under the light they are used under.
render::Light lightBesideLens(const render::Camera& camera, float rightMm = 70.0f, float upMm = 70.0f,
                              float forwardMm = 20.0f);

/// FNV-1a over the positions (mm), triangles, UVs, the material (layers, maps), the camera and
/// lights of `frame`, the tracer's settings and the time budget.
std::uint64_t truthKey(std::span<const Float3> positions, const SurfaceMesh& mesh,
                       const truth::TruthMaterial& material, const render::Scene& frame,
                       const truth::PathTraceSettings& settings, double budgetS);

/// "truth_v<tracer version>_<frame>_<16 hex digits>.bin".
std::string truthCacheName(const std::string& frame, std::uint64_t key);

/// The cached image, or none when the file is missing or unreadable.
std::optional<truth::TruthImage> readTruthCache(const std::filesystem::path& file);

/// Writes the image atomically (a temporary file renamed). Errors name the file.
Result<void> writeTruthCache(const std::filesystem::path& file, const truth::TruthImage& image);

/// Fills result.output: atlas.json, atlas.md, atlas.csv and the chart atlas.png.
void writeAtlasReport(AtlasResult& result, const AtlasConfig& config,
                      const std::vector<std::pair<std::string, std::string>>& skipped);

}  // namespace tissue::studies::detail
