#pragma once
/// \file
/// An organ made ready for texture-space diffusion (d'Eon et al. 2007; Jimenez et al. 2008): its
/// own UVs when usable, else the scene module's automatic atlas (scene::loadOrganAssets, computed
/// once), with smooth normals and tangent frames; d'Eon & Luebke's six-Gaussian skin profile read
/// from its table, or fewer Gaussians fitted to it (optics::fitGaussians); and that profile
/// sampled for the CPU reference convolution. GL-free. Lengths in mm, variances in mm^2.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/core/types.h"
#include "tissue/render/renderer.h"
#include "tissue/render/texture_space_math.h"
#include "tissue/render/texture_space_reference.h"

namespace tissue::studies {

/// An organ as texture-space diffusion draws it.
struct TsdOrgan {
  SurfaceMesh mesh;  ///< render vertices (split at the atlas's or the file's seams), mm
  std::vector<Float3> normals;
  std::vector<Float4> tangents;
  bool atlas = false;      ///< true: the automatic UV atlas replaced missing or unusable UVs
  std::size_t charts = 0;  ///< atlas charts (0 with the file's UVs)
  float uvDensity = 0.0f;  ///< sqrt(UV area / surface area), UV units per mm
  Float3 lo, hi;           ///< bounds, mm
  render::MeshArrays arrays() const {
    return {mesh.positions, normals, tangents, mesh.uvs, mesh.triangles, {}};
  }
};

/// `mesh` (mm) with smooth normals per geometric vertex and tangent frames from its UVs (if any).
TsdOrgan tsdOrganOf(SurfaceMesh mesh);

/// Loads a mesh (mm per file unit `scale`) and gives it usable UVs: its own when present and
/// free of overlaps, else mesh::computeUvAtlas on its welded surface (scene::loadOrganAssets).
Result<TsdOrgan> loadTsdOrgan(const std::filesystem::path& path, float scale);

/// The same without the atlas: the mesh's own UVs (tangent frames from them) or none.
Result<TsdOrgan> loadRenderMesh(const std::filesystem::path& path, float scale);

/// d'Eon & Luebke's skin profile as `count` Gaussians (2, 4 or 6), from `table`
/// (shared/reference/deon_skin_gaussians.tsv: rows 'variance w_R w_G w_B'): the file's six, or
/// fewer fitted to the six-term profile by optics::fitGaussians (Jimenez et al. 2008 eq. 2).
Result<std::vector<render::ProfileGaussian>> skinGaussians(const std::filesystem::path& table, int count);

/// The six-term skin profile sampled for the CPU reference, and its cutoff radius (mm): 3.5
/// sigma of the widest term.
render::RadialProfileTable skinProfileTable(const std::vector<render::ProfileGaussian>& six, float& cutoffMm);

}  // namespace tissue::studies
