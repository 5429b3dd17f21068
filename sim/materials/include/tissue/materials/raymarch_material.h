#pragma once
/// \file
/// The bridge from a layered material (tissue::subsurface, GL-free) to the renderer's ray-march
/// method (render::RayMarchSettings), shared by tissue-sim (render --method raymarch, the demo,
/// the ray-march studies) and tissue-viewer: the layer stack of data/materials/<stem>.json, its
/// RGBA subsurface map (the layer boundaries, François et al. 2006 §2.1) and the mesh's texture
/// units per mm. Lengths in mm, coefficients in mm^-1.

#include <filesystem>
#include <span>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/shading.h"
#include "tissue/subsurface/layer_stack.h"

namespace tissue::materials {

/// A layered material ready for ray marching on one mesh.
struct RayMarchMaterial {
  subsurface::LayerStack stack;  ///< layers (mm^-1), depth scale (mm), the boundary maps for the CPU model
  Image8 subsurfaceMap;          ///< the RGBA map the boundaries come from; upload as LinearData
  float uvPerMm = 0.0f;          ///< texture units per mm of the mesh (subsurface::uvPerMmOf)
};

/// Loads the layer stack of `materialFile` (data/materials/<stem>.json; its relative paths from
/// `dataDir`) and the subsurface map `mapFile` (RGBA PNG), and measures the texture units per mm
/// of the mesh (`positions` mm, `uvs`, `triangles`). Errors name the file and say that ray
/// marching needs a data/ mesh with a material file.
Result<RayMarchMaterial> loadRayMarchMaterial(const std::filesystem::path& materialFile,
                                              const std::filesystem::path& dataDir,
                                              const std::filesystem::path& mapFile,
                                              std::span<const Float3> positions, std::span<const Float2> uvs,
                                              std::span<const Triangle> triangles);

/// `march` (its march and adaptive-quality fields kept) with `material`: its layers (Schlick k
/// from g, optics::schlickKFromG), the uploaded subsurface map `map`, depth scale (mm) and
/// texture units per mm.
render::RayMarchSettings withRayMarchMaterial(render::RayMarchSettings march,
                                              const RayMarchMaterial& material, render::TextureHandle map);

}  // namespace tissue::materials
