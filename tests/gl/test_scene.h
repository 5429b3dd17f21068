#pragma once
// A procedural test scene that needs no mesh module: a UV sphere with analytic normals and
// tangent frames, and procedural normal and base-colour maps.
#include <vector>

#include "tissue/core/image.h"
#include "tissue/render/renderer.h"
#include "tissue/render/texture_space_math.h"

namespace tissue::test {

/// A UV sphere (radius mm) as render arrays; u = longitude / 2 pi, v = latitude, 0 at the south pole.
struct SphereMesh {
  std::vector<Float3> positions, normals;
  std::vector<Float4> tangents;
  std::vector<Float2> uvs;
  std::vector<Triangle> triangles;
  render::MeshArrays arrays() const { return {positions, normals, tangents, uvs, triangles, {}}; }
};

/// `rings` latitude bands, `segments` longitude bands (a seam column is duplicated).
SphereMesh makeSphere(float radiusMm, int rings, int segments);

/// A flat square patch of side `sizeMm` centred on (0, 0, zMm), facing +z, `cells` quads a side;
/// u along +x, v along +y.
SphereMesh makePatch(float sizeMm, int cells, float zMm);

/// A flat sx x sy mm patch of n x n quads in z = 0 facing +z, its x scaled by `stretchX` (the UVs
/// are not), uv = (x / sx, y / sy) inset by 2% (texture-space tests: no texel at the map's edge).
SphereMesh makeInsetPatch(int n, float sx, float sy, float stretchX = 1.0f);

/// A bumpy tangent-space normal map: height sin(2 pi 8 u) sin(2 pi 5 v) + ridges along u, so its
/// gradient has components along both u and v (so the handedness w matters).
Image8 makeBumpyNormalMap(int size);
/// The flat normal map (0, 0, 1).
Image8 makeFlatNormalMap(int size);
/// A base colour with a gentle stripe pattern (sRGB).
Image8 makeBaseColor(int size);

/// Mean of the red channel of `image` over columns [x0, x1) and rows [y0, y1).
double meanRedOver(const render::FloatImage& image, int x0, int x1, int y0, int y1);

/// The golden images' sphere (radius 40 mm) with the stripe base colour and the bumpy normal map,
/// uploaded to `renderer`; false members where an upload failed.
struct GoldenSphere {
  Result<render::MeshHandle> mesh;
  Result<render::TextureHandle> baseColor, normalMap;
  explicit operator bool() const { return mesh && baseColor && normalMap; }
};
GoldenSphere uploadGoldenSphere(render::Renderer& renderer);

/// d'Eon & Luebke's six skin Gaussians (../shared/reference/deon_skin_gaussians.tsv): variances
/// mm^2 and RGB weights, each channel summing to 1.
std::vector<render::ProfileGaussian> deonSkinGaussians();

/// Texture-space settings with deonSkinGaussians(), T_max = `mapSize`, the three optimisations on
/// or off.
render::TextureSpaceSettings skinTextureSpace(int mapSize, bool optimised);

/// The scene the golden images are rendered with (256 x 256).
render::Scene goldenScene();

}  // namespace tissue::test
