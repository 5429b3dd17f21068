#pragma once
/// \file
/// The scenes of Jimenez and Gutierrez 2008 Table 1 on our renderer: a row of up to 16 instances
/// of one organ, 1.1 organ widths apart (one mesh per instance: scene objects have no
/// transform), and the camera at a multiple of the organ's size from the middle n of them,
/// looking down and along -z with the light above right. GL: the renderer's context current.

#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/studies/texture_space_organ.h"

namespace tissue::studies {

/// The table's organ counts and camera distances (x the organ's size).
inline constexpr int kTsdBenchObjects[] = {1, 2, 4, 8, 16};
inline constexpr float kTsdBenchDistances[] = {1.0f, 2.0f, 4.0f, 8.0f, 20.0f, 40.0f};

/// The camera `distance` mm from `target` (mm), looking down and along -z, the light above right;
/// near and far planes around an organ of `organSize` mm in a row `rowLength` mm long.
render::Scene tsdBenchScene(Float3 target, float distance, float organSize, float rowLength);

/// The row of organs uploaded to one renderer.
struct TsdOrganRow {
  static constexpr int kMaxObjects = 16;
  std::vector<render::MeshHandle> meshes;  ///< instance i centred at x_i = (i - 7.5) 1.1 width
  float widthMm = 0.0f;                    ///< mm, the organ's x extent
  float sizeMm = 0.0f;                     ///< mm, its bounding-box diagonal
  /// mm, the centre of instance `i`.
  float rowX(int i) const;
  /// The middle `n` organs with `method`, the camera `distance` mm from their centre.
  render::Scene sceneOf(int n, float distance, const render::TextureSpaceSettings& method) const;
};

/// Uploads kMaxObjects copies of `organ`, each centred on its place in the row.
Result<TsdOrganRow> uploadOrganRow(render::Renderer& renderer, const TsdOrgan& organ);

}  // namespace tissue::studies
