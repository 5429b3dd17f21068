#pragma once
/// \file
/// The bridge from a layered material (tissue::subsurface, GL-free) to the renderer's ray-march
/// method (render::RayMarchSettings), shared by tissue-sim (render --method raymarch, the demo,
/// the ray-march studies) and tissue-viewer: the layer stack of data/materials/<stem>.json, its
/// RGBA subsurface map (the layer boundaries, François et al. 2006 §2.1) and the mesh's texture
/// units per mm. Lengths in mm, coefficients in mm^-1.

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/render/shading.h"
#include "tissue/subsurface/layer_stack.h"

namespace tissue::materials {

/// A layered material ready for ray marching on one mesh (tissue-sim builds it from
/// scene::readMaterialFile and scene::layerStack).
struct RayMarchMaterial {
  subsurface::LayerStack stack;  ///< layers (mm^-1), depth scale (mm), the boundary maps for the CPU model
  Image8 subsurfaceMap;          ///< the RGBA map the boundaries come from; upload as LinearData
  float uvPerMm = 0.0f;          ///< texture units per mm of the mesh (subsurface::uvPerMmOf)
};

/// `march` (its march and adaptive-quality fields kept) with `material`: its layers (Schlick k
/// from g, optics::schlickKFromG), the uploaded subsurface map `map`, depth scale (mm) and
/// texture units per mm.
render::RayMarchSettings withRayMarchMaterial(render::RayMarchSettings march,
                                              const RayMarchMaterial& material, render::TextureHandle map);

}  // namespace tissue::materials
