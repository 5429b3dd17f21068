#pragma once
// The irradiance-map pass of texture-space diffusion as a reusable component (d'Eon et al.
// 2007 with Jimenez and Gutierrez 2008's culled (§3), depth-sized (§4) and clipped (§5) maps).
// The layered-parallax method uses it as its lightmap. Two lightings: one point light
// (IrradianceFrame's light fields, texture_space/irradiance.frag), or the pipeline's scene
// lights with shadows (IrradianceLighting, texture_space/irradiance_scene.frag). It draws a mesh's vertex
// array (attribute 0 position mm, 1 normal, 3 uv) at its texture coordinates into RGBA16F targets of T_max^2
// texels, of which the viewport (0, 0, T, T) is used; state is set, not restored.
#include <array>
#include <span>
#include <vector>

#include "../lights.h"
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/gl/shader_library.h"
#include "tissue/render/scene.h"
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

/// The view and light of one frame, and the object's transform and bounds (for d of eq. 3).
struct IrradianceFrame {
  Mat4 view{};                ///< world (mm) to eye (mm), column-major
  Mat4 projection{};          ///< eye to clip, column-major
  Float3 eye;                 ///< camera position, mm
  Float3 boundsLo, boundsHi;  ///< the object's world bounding box, mm (through `model`)
  /// Object (mm) to world (mm), column-major (SceneObject::model; it supersedes the former
  /// instance offset: an instance's translation is its model's).
  Mat4 model = kIdentityModel;
  /// (M3^-1)^T of `model`, column-major 3x3: normals.
  std::array<float, 9> normalMatrix{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  Float3 lightPosition;  ///< mm
  Float3 lightRadiance;  ///< linear RGB
  Float3 ambient;        ///< linear RGB irradiance added everywhere
  /// A double-sided object (SceneObject::doubleSided; pipeline lighting only): each texel is lit
  /// on the side the camera sees, and no texel is culled (one of its two sides always faces
  /// the camera within Jimenez §3's 105 degrees).
  bool twoSided = false;
};

/// The frame's camera as an irradiance frame (view, projection, eye; the rest default), for
/// texture space and parallax alike.
IrradianceFrame cameraIrradianceFrame(const Camera& camera, int width, int height);

/// The pipeline's light for the irradiance pass: every light of the frame through
/// common/lights.glsl with its shadow map, transmission, and the object's textures, so that the
/// map holds what the separable geometry pass writes to its diffuse target (for p = 1).
/// Textures go on units 0 (base colour), 1 (normal map) and 2 (shadow maps), as surface shaders.
struct IrradianceLighting {
  const LightFrame* lights = nullptr;  ///< the frame's lights (required)
  GLuint shadowMaps = 0;               ///< GL_TEXTURE_2D_ARRAY of light distances, mm
  GLuint baseColor = 0;                ///< sRGB albedo texture
  GLuint normalMap = 0;                ///< tangent-space normal map; 0: the vertex normals shade
  float albedoPreScatter = 1.0f;  ///< p: the map holds albedo^p x E (E: IrradianceFrame::ambient + lights)
  std::span<const Float4> transmittance;  ///< {T_R, T_G, T_B, thickness mm} rows; empty: none
  float transmissionShrinkMm = 0.5f;      ///< mm pushed inside before the thickness lookup
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
  /// The same with the scene's lights instead of IrradianceFrame's single light (whose light
  /// fields are ignored; ambient is used).
  Result<void> render(GLuint vertexArray, GLsizei indexCount, const IrradianceFrame& frame,
                      const IrradianceMapSettings& settings, const IrradianceLighting& lighting,
                      bool writePositions = false);

  GLuint irradiance() const { return m_irradiance.id(); }  ///< rgb E, a = visible
  GLuint stretch() const { return m_stretch.id(); }        ///< rg mm per UV unit
  GLuint position() const { return m_position.id(); }      ///< xyz world mm (when written)
  GLuint framebuffer() const { return m_framebuffer.id(); }
  /// Depth renderbuffer (T_max^2): after a scene-lit render, 0 where a texel is drawn and visible,
  /// 1 where culled or empty, so later passes can skip those texels by an early depth test (on
  /// llvmpipe a branch in the shader saves nothing: both sides run, masked).
  GLuint visibilityDepth() const { return m_depth.id(); }
  /// True when the last render wrote visibilityDepth() (the scene-lit overload).
  bool visibilityInDepth() const { return m_visibilityInDepth; }
  int maxSize() const { return m_maxSize; }  ///< T_max, texels
  int size() const { return m_size; }        ///< T of the last render, texels
  float scale() const { return m_scale; }    ///< s of the last render (T / T_max)

  /// An empty map (create() makes a usable one).
  IrradianceMap() = default;

 private:
  // Steps 1-3 of both renders: map size, clear, state, the uniforms every variant has.
  void begin(GLuint program, const IrradianceFrame& frame, const IrradianceMapSettings& settings,
             bool writePositions);
  Result<void> draw(GLuint vertexArray, GLsizei indexCount, bool clip);
  const gl::GlApi* m_gl = nullptr;
  gl::Program m_program;
  gl::Program m_scene[2];  // scene lights: vertex normals, normal-mapped (TISSUE_NORMAL_MAP)
  gl::Texture m_irradiance, m_stretch, m_position;
  gl::Framebuffer m_framebuffer;
  gl::Renderbuffer m_depth;
  bool m_visibilityInDepth = false;
  int m_maxSize = 0, m_size = 0;
  float m_scale = 1.0f;
  GLint m_lightPosition = -1, m_lightRadiance = -1;
};

/// Reads the `size` x `size` texels at the origin of `framebuffer`'s `attachment` as float RGBA
/// (rows bottom to top, increasing v), for CPU references.
Result<std::vector<Float4>> readTexels(const gl::GlApi& gl, GLuint framebuffer, GLenum attachment, int size);

/// A float texture of `size`^2 texels, linear filtering, clamped; `internal` e.g. GL_RGBA16F.
Result<gl::Texture> createFloatTexture(const gl::GlApi& gl, int size, GLenum internal);

}  // namespace tissue::render
