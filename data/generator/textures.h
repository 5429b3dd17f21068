#pragma once
/// \file
/// The layer textures of one mesh (François et al. 2006 §2.1 Fig. 4; Norberg 2010 §2.1.2 Fig. 2
/// and §2.2 Fig. 8), computed in the mesh's UV space. Texel (x, y), rows top to bottom, has
/// texture coordinate ((x + 0.5) / N, 1 - (y + 0.5) / N).

#include "tissue/core/image.h"
#include "uv_layout.h"

namespace tissue::datagen {

/// The five textures of one mesh.
struct LayerTextures {
  /// RGBA, each channel the depth of a layer boundary below the surface along the normal, in units
  /// of the material's depth_scale_mm; non-decreasing R <= G <= B <= A at every texel. Layers:
  /// outer [0, R), fat lobules [R, G), thin vessels [G, B), thick vessels [B, A), deep [A, inf).
  Image8 subsurface;
  Image8 baseColor;  ///< RGB, outer layer diffuse colour (sRGB)
  Image8 normalMap;  ///< RGB tangent-space normal, +z out, OpenGL convention (green = +v)
  Image8 opacity;    ///< 1 channel, outer layer opacity (lower over vessels)
  Image8 innerBase;  ///< RGB, inner layer base colour with clearly visible vessels (sRGB)
};

/// Generates the textures of `kind` at `size` x `size` texels on `threads` threads; the result
/// does not depend on the thread count.
LayerTextures generateTextures(MeshKind kind, int size, int threads);

}  // namespace tissue::datagen
