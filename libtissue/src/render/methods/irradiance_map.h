#pragma once
// The irradiance-map pass of texture-space diffusion as a reusable component (d'Eon et al.
// 2007 with Jimenez and Gutierrez 2008's culled (§3), depth-sized (§4) and clipped (§5) maps).
// The layered-parallax method uses it as its lightmap. It draws a mesh's vertex array (attribute
// 0 position mm, 1 normal, 3 uv) at its texture coordinates into RGBA16F targets of T_max^2
// texels, of which the viewport (0, 0, T, T) is used; state is set, not restored.
#include <array>

#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/texture_space_math.h"

namespace tissue::render {

/// Which optimisations the irradiance pass applies.
struct IrradianceMapSettings {
  bool cull = true;                  ///< §3: alpha = 0 where the normal faces more than 105 deg from the eye
  bool clip = true;                  ///< §5: clip against the view frustum in eye space (eq. 5-6)
  bool depthSize = true;             ///< §4: map size T = s T_max (eq. 3-4)
  float clipD = 1.0f;                ///< D of eq. 5; > 1 keeps an off-screen margin
  float referenceDistanceMm = 0.0f;  ///< d_ref of eq. 3, mm
};

/// The view and light of one frame, and the object's bounds (for d of eq. 3).
struct IrradianceFrame {
  Mat4 view{};                ///< world (mm) to eye (mm), column-major
  Mat4 projection{};          ///< eye to clip, column-major
  Float3 eye;                 ///< camera position, mm
  Float3 boundsLo, boundsHi;  ///< the object's world bounding box, mm
  Float3 offsetMm;            ///< translation added to the mesh's positions (instances), mm
  Float3 lightPosition;       ///< mm
  Float3 lightRadiance;       ///< linear RGB
  Float3 ambient;             ///< linear RGB irradiance added everywhere
};

/// The irradiance, stretch and (optionally) position maps of one object.
class IrradianceMap {
 public:
  /// Builds the program and T_max^2 targets (RGBA16F irradiance and stretch, RGBA32F position).
  static Result<IrradianceMap> create(const gl::GlApi& gl, const gl::ShaderLibrary& library, int maxSize);

  /// Clears the used part and draws the mesh into it. `vertexArray` holds the mesh, with
  /// `indexCount` indices (GL_UNSIGNED_INT triangles).
  Result<void> render(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                      const IrradianceMapSettings& settings, bool writePositions = false);

  GLuint irradiance() const { return m_irradiance.id(); }  ///< rgb E, a = visible
  GLuint stretch() const { return m_stretch.id(); }        ///< rg mm per UV unit
  GLuint position() const { return m_position.id(); }      ///< xyz world mm (when written)
  GLuint framebuffer() const { return m_framebuffer.id(); }
  int maxSize() const { return m_maxSize; }  ///< T_max, texels
  int size() const { return m_size; }        ///< T of the last render, texels
  float scale() const { return m_scale; }    ///< s of the last render (T / T_max)

  /// An empty map (create() makes a usable one).
  IrradianceMap() = default;

 private:
  const gl::GlApi* m_gl = nullptr;
  gl::Program m_program;
  gl::Texture m_irradiance, m_stretch, m_position;
  gl::Framebuffer m_framebuffer;
  int m_maxSize = 0, m_size = 0;
  float m_scale = 1.0f;
  GLint m_view = -1, m_clipPlanes = -1, m_clip = -1, m_cull = -1, m_cullCosine = -1, m_mapSize = -1,
        m_offset = -1, m_lightPosition = -1, m_lightRadiance = -1, m_ambient = -1;
};

/// A float texture of `size`^2 texels, linear filtering, clamped; `internal` e.g. GL_RGBA16F.
Result<gl::Texture> createFloatTexture(const gl::GlApi& gl, int size, GLenum internal);

}  // namespace tissue::render
