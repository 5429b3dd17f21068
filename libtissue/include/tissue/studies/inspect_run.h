#pragma once
/// \file
/// tissue-sim inspect's run: a scenario (or a recorded session replayed) taken to frame N through
/// the trainee's loop, then every VTK inspection view of that frame written (PNG with colour bars
/// and a .vtp each; inspect/inspection_views.h), with `pvdDir` also the ParaView series of frames
/// 1..N (inspect/pvd_series.h) and what it cost. The command parses, calls and prints.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/scene.h"
#include "tissue/scene/scene.h"
#include "tissue/truth/ray_mesh.h"

namespace tissue::studies {

/// What to inspect and where to write (plain struct with defaults).
struct InspectConfig {
  std::filesystem::path input{};   ///< a scenario (data/scenarios/*.json) or a session file
  long frame = -1;                 ///< frames to simulate first; -1: the scenario's (session's) last
  std::filesystem::path outDir{};  ///< the views' folder
  std::filesystem::path pvdDir{};  ///< non-empty: the ParaView series of frames 1..N
  int width = 1000;                ///< pixels of each view
  int height = 750;                ///< pixels
  /// Non-empty ("lit", "separable", "texture-space", "ray-march", "parallax"): also the
  /// truth_error view, that method's error against the path-traced truth of the same frame.
  std::string truthMethod{};
  double truthSeconds = 30.0;  ///< s of path tracing for the truth (its noise is reported)
  int truthWidth = 160;        ///< pixels of the method's image and of the truth
  int truthHeight = 120;       ///< pixels
  int threads = 0;             ///< the truth's worker threads; 0: all cores
};

/// Per vertex, the value of the pixel it projects to under the pinhole `camera` (the image
/// `width` x `height`, rows top to bottom, as render::Camera and the truth's pinhole), where the
/// vertex is visible: no triangle of `rays` nearer along the ray from the eye. NaN where it is
/// hidden, behind the eye, outside the image or on a NaN pixel.
std::vector<float> pixelValuesAtVertices(const render::Camera& camera, int width, int height,
                                         std::span<const float> perPixel, std::span<const Float3> positionsMm,
                                         const truth::RayMesh& rays);

/// The per-pixel error behind the truth_error view: |M - T| (RGB distance) over the RMS of |T|
/// on the truth's covered pixels, so that the mean of its square over them is the atlas's rel
/// RMS squared; then averaged over each covered pixel's covered 3 x 3 neighbourhood (the
/// truth's noise is per pixel). NaN off the organ. `method` and `truth` are #width*#height.
std::vector<float> relativeErrorImage(std::span<const Float3> method, std::span<const Float3> truth,
                                      std::span<const std::uint8_t> covered, int width, int height);

/// Runs `config.input` in a simulation-only scene of `scene`'s settings (material files, shared
/// meshes) and writes the views. Returns the report as a JSON object's text: input, frame, out,
/// views [{view, png, vtp, render_ms, write_ms}] and, with pvdDir, pvd {file, frames,
/// snapshot_ms, frame_file_ms, collection_ms} (each {median, p99, max}) and, with truthMethod,
/// truth_error {method, width, height, truth_spp, truth_s, rel_rms, noise_rel_rms,
/// visible_vertices} (the method drawn through a scene on a headless context of `scene`'s). A frame past the
/// end or a session of another mesh gives one error naming the file and the fix.
Result<std::string> inspectRun(const InspectConfig& config, scene::SceneSettings scene);

}  // namespace tissue::studies
