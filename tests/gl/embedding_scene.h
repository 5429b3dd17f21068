#pragma once
// Shared pieces of the embedding tests (issue 12): one object of each shading method on a
// procedural sphere with planes and textures, and a host's own flat-colour drawing (a program,
// a vertex array, a quad) for tests that play the host application.
#include <array>
#include <string>
#include <vector>

#include "test_scene.h"
#include "tissue/gl/gl_api.h"
#include "tissue/render/renderer.h"

namespace tissue::test {

inline constexpr render::ShadingMethod kAllMethods[] = {
    render::ShadingMethod::Lit, render::ShadingMethod::Separable, render::ShadingMethod::TextureSpace,
    render::ShadingMethod::RayMarch, render::ShadingMethod::Parallax};

/// `method`'s name as a gtest parameter name ("ray-march" -> "ray_march").
std::string methodTestName(render::ShadingMethod method);

/// A UV sphere with local planes (N_S, d mm) per vertex for the ray march: N_S tilted from the
/// normal toward the tangent, d = 0.3 mm, so that transforming them is a real test.
struct PlanarSphere {
  SphereMesh mesh;
  std::vector<Float4> planes;
  render::MeshArrays arrays() const {
    render::MeshArrays a = mesh.arrays();
    a.planes = planes;
    return a;
  }
};
PlanarSphere makePlanarSphere(float radiusMm, int rings, int segments);

/// Textures every method's settings may name, uploaded to one renderer.
struct MethodTextures {
  render::TextureHandle baseColor, normalMap, subsurface;
};
Result<MethodTextures> uploadMethodTextures(render::Renderer& renderer);

/// Small but complete settings of `method` (quick on llvmpipe): a 9-tap Gaussian separable kernel
/// with transmittance, d'Eon's skin Gaussians on a 256-texel map, a five-layer ray march of one
/// constant subsurface map (24 samples, no jitter), one parallax layer on a 256-texel lightmap.
/// `uvPerMm`: the ray march's texture units per world mm.
render::MethodSettings methodSettings(render::ShadingMethod method, const MethodTextures& textures,
                                      float uvPerMm);

/// An object of `mesh` with the base colour, normal map and `methodSettings(method, ...)`.
render::SceneObject methodObject(render::ShadingMethod method, render::MeshHandle mesh,
                                 const MethodTextures& textures, float uvPerMm);

/// A column-major 4x4 matrix as the renderer's SceneObject::model wants it.
using Mat4 = std::array<float, 16>;

/// The host application's drawing: flat-coloured quads through its own program and vertex
/// array, with whatever depth state the caller sets.
class HostDrawer {
 public:
  explicit HostDrawer(const gl::GlApi& gl);
  ~HostDrawer();
  HostDrawer(const HostDrawer&) = delete;
  HostDrawer& operator=(const HostDrawer&) = delete;
  bool ok() const { return m_program != 0; }
  /// The quad of corners a, b, c, d (world mm, in order around it) through `viewProjection`
  /// (column-major, world to clip) in `rgba`.
  void quad(const Mat4& viewProjection, const std::array<Float3, 4>& corners, const Float4& rgba) const;
  GLuint program() const { return m_program; }
  GLuint vertexArray() const { return m_vertexArray; }
  GLuint buffer() const { return m_buffer; }

 private:
  const gl::GlApi& m_gl;
  GLuint m_program = 0, m_vertexArray = 0, m_buffer = 0;
};

/// The host's projection * view of `camera` for an image of `aspect` (as the renderer's).
Mat4 hostViewProjection(const render::Camera& camera, float aspect);

}  // namespace tissue::test
