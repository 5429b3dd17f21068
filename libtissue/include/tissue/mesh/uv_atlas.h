#pragma once
/// \file
/// Automatic UV chart atlas for meshes without usable texture coordinates (texture-space
/// diffusion needs a unique parameterisation: every surface point one texel, no overlaps).
/// Three steps, computed once on the rest shape and kept through deformation (the charts move
/// with the material): segmentation into disk-like charts by region growing in a normal cone,
/// a least-squares conformal map per chart (Lévy et al. 2002, LSCM), and shelf packing of the
/// charts at one common texel density with a gutter in texels.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::mesh {

/// Atlas settings.
struct AtlasSettings {
  float maxChartNormalDeviationDeg = 50.0f;  ///< degrees; a chart's triangles stay inside this cone
                                             ///< around the normal of its seed triangle
  int resolution = 1024;                     ///< texels; the map the gutter is measured in (square)
  float gutterTexels = 4.0f;                 ///< texels between charts and to the map border
  int maxSplitDepth = 12;                    ///< limit of recursive splits of folding/non-disk charts
};

/// The atlas: render vertices split at chart seams. Triangle i of the output is triangle i of
/// the input, so per-triangle data keep their order.
struct UvAtlas {
  std::vector<Float2> uvs;                     ///< #R unitless, in [0, 1]^2
  std::vector<Triangle> triangles;             ///< #F render-vertex indices, counter-clockwise
  std::vector<std::uint32_t> originalVertex;   ///< #R input vertex of each render vertex
  std::vector<std::uint32_t> chartOfTriangle;  ///< #F chart index
  std::uint32_t chartCount = 0;
  float texelsPerMm = 0.0f;  ///< texels per mm at `resolution` (the common density), 1/mm
};

/// Distortion of a parameterisation (per-triangle singular values s1 >= s2 of the 3D -> UV
/// Jacobian, after scaling UV so that total UV area equals total 3D area). All are area
/// weighted over the surface; 1 is ideal for each.
struct AtlasDistortion {
  double l2Stretch = 0.0;            ///< sqrt(mean((s1^2 + s2^2) / 2)), Sander et al. 2001
  double meanAngleRatio = 0.0;       ///< mean s1 / s2 (conformality)
  double maxAngleRatio = 0.0;        ///< largest s1 / s2
  double meanAreaRatio = 0.0;        ///< mean max(s1 s2, 1 / (s1 s2)) (area distortion)
  double maxAreaRatio = 0.0;         ///< largest max(s1 s2, 1 / (s1 s2))
  double coverage = 0.0;             ///< fraction of [0, 1]^2 covered by triangles, unitless
  std::size_t flippedTriangles = 0;  ///< UV triangles with non-positive signed area
};

/// Builds an atlas for a triangle mesh.
/// \param positions #V positions, mm (the rest shape)
/// \param triangles #F triangles, counter-clockwise seen from outside; a manifold mesh
/// \return the atlas, or an Error for empty input, out-of-range indices, non-finite positions
///         or a chart that could not be flattened within `maxSplitDepth` splits
Result<UvAtlas> computeUvAtlas(std::span<const Float3> positions, std::span<const Triangle> triangles,
                               const AtlasSettings& settings = {});

/// Measures the distortion of `uvs` on `triangles` over `positions` (mm).
/// \param positions #R positions, mm, indexed by `triangles`
/// \param uvs       #R texture coordinates, indexed by `triangles`
AtlasDistortion measureAtlasDistortion(std::span<const Float3> positions, std::span<const Float2> uvs,
                                       std::span<const Triangle> triangles);

/// UVs are usable for texture-space methods when every vertex has one and no two triangles
/// overlap in UV space (triangles that only share an edge or a vertex do not overlap).
/// \param uvs       #R texture coordinates (empty: not usable)
/// \param triangles #F triangles indexing `uvs`
/// \param positionCount number of render vertices the mesh has; `uvs` must match it
bool hasUsableUvs(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                  std::size_t positionCount);

/// Number of triangle pairs whose UV interiors overlap (at most `maxCount` are counted).
std::size_t countUvOverlaps(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                            std::size_t maxCount = 1);

}  // namespace tissue::mesh
