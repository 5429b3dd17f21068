#pragma once
// Saves the GL state the renderer touches and restores it on destruction, so a host's state
// survives a render call (Filament's rule: the engine's GL use must not leak into the host).
#include <array>

#include "tissue/gl/gl_api.h"

namespace tissue::render {

/// The list of saved state is documented at Renderer::renderTo. Besides saving, the
/// constructor sets the baseline every pass assumes for the state no pass sets itself (stencil
/// test, polygon offset, alpha-to-coverage, sample coverage, rasterizer discard, primitive
/// restart, logic op and clip distances off; polygon mode fill; no sampler objects on units
/// 0-7; no pixel pack or unpack buffer; unpack skips 0), so that a host's unusual settings cannot reach the
/// renderer's passes.
class StateGuard {
 public:
  explicit StateGuard(const gl::GlApi& gl);
  ~StateGuard();
  StateGuard(const StateGuard&) = delete;
  StateGuard& operator=(const StateGuard&) = delete;

  /// The capabilities the constructor disables (and the destructor restores).
  static constexpr std::array<GLenum, 13> kDisabledCaps = {
      GL_STENCIL_TEST,       GL_POLYGON_OFFSET_FILL, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE,
      GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART,   GL_COLOR_LOGIC_OP,           GL_CLIP_DISTANCE0,
      GL_CLIP_DISTANCE1,     GL_CLIP_DISTANCE2,      GL_CLIP_DISTANCE3,           GL_CLIP_DISTANCE4,
      GL_CLIP_DISTANCE5};
  /// The renderer binds textures on units 0..kUnits-1 only.
  static constexpr int kUnits = 8;

 private:
  const gl::GlApi& m_gl;
  GLint m_drawFramebuffer = 0, m_readFramebuffer = 0, m_renderbuffer = 0;
  GLint m_viewport[4] = {}, m_scissorBox[4] = {};
  GLint m_program = 0, m_vertexArray = 0, m_arrayBuffer = 0;
  GLint m_activeTexture = 0, m_texture2d[kUnits] = {}, m_texture2dArray[kUnits] = {},
        m_texture2dMultisample[kUnits] = {}, m_sampler[kUnits] = {};
  // GL_BLEND_SRC_RGB, _DST_RGB, _SRC_ALPHA, _DST_ALPHA, _EQUATION_RGB, _EQUATION_ALPHA
  GLint m_blendState[6] = {};
  GLint m_depthFunc = 0, m_cullMode = 0, m_frontFace = 0, m_polygonMode[2] = {};
  GLint m_packAlignment = 0, m_unpackAlignment = 0, m_unpackRowLength = 0, m_unpackSkipPixels = 0,
        m_unpackSkipRows = 0, m_pixelUnpackBuffer = 0, m_pixelPackBuffer = 0;
  GLboolean m_depthMask = GL_TRUE, m_colorMask[4] = {};
  GLfloat m_clearColor[4] = {};
  GLdouble m_clearDepth = 1.0;
  GLboolean m_depthTest = GL_FALSE, m_cullFace = GL_FALSE, m_blend = GL_FALSE, m_scissorTest = GL_FALSE,
            m_srgb = GL_FALSE, m_multisample = GL_FALSE;
  std::array<GLboolean, kDisabledCaps.size()> m_disabledCaps{};
};

}  // namespace tissue::render
