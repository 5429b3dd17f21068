#include "state_guard.h"

#include <array>

namespace tissue::render {
namespace {
// The blend state saved in StateGuard::m_blendState, in its order.
constexpr std::array<GLenum, 6> kBlendState = {GL_BLEND_SRC_RGB,      GL_BLEND_DST_RGB,
                                               GL_BLEND_SRC_ALPHA,    GL_BLEND_DST_ALPHA,
                                               GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA};
void setEnabled(const gl::GlApi& gl, GLenum cap, GLboolean on) {
  if (on) {
    gl.Enable(cap);
  } else {
    gl.Disable(cap);
  }
}
}  // namespace

StateGuard::StateGuard(const gl::GlApi& gl) : m_gl(gl) {
  gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_drawFramebuffer);
  gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &m_readFramebuffer);
  gl.GetIntegerv(GL_RENDERBUFFER_BINDING, &m_renderbuffer);
  gl.GetIntegerv(GL_VIEWPORT, m_viewport);
  gl.GetIntegerv(GL_SCISSOR_BOX, m_scissorBox);
  gl.GetIntegerv(GL_CURRENT_PROGRAM, &m_program);
  gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &m_vertexArray);
  gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &m_arrayBuffer);
  gl.GetIntegerv(GL_ACTIVE_TEXTURE, &m_activeTexture);
  for (int unit = 0; unit < kUnits; ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &m_texture2d[unit]);
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &m_texture2dArray[unit]);
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &m_texture2dMultisample[unit]);
    gl.GetIntegerv(GL_SAMPLER_BINDING, &m_sampler[unit]);
    // A host's sampler object would override the renderer's texture parameters.
    if (m_sampler[unit] != 0) gl.BindSampler(static_cast<GLuint>(unit), 0);
  }
  gl.ActiveTexture(static_cast<GLenum>(m_activeTexture));
  gl.GetIntegerv(GL_DEPTH_FUNC, &m_depthFunc);
  gl.GetIntegerv(GL_CULL_FACE_MODE, &m_cullMode);
  gl.GetIntegerv(GL_FRONT_FACE, &m_frontFace);
  gl.GetIntegerv(GL_POLYGON_MODE, m_polygonMode);
  gl.GetIntegerv(GL_PACK_ALIGNMENT, &m_packAlignment);
  gl.GetIntegerv(GL_UNPACK_ALIGNMENT, &m_unpackAlignment);
  gl.GetIntegerv(GL_UNPACK_ROW_LENGTH, &m_unpackRowLength);
  gl.GetIntegerv(GL_UNPACK_SKIP_PIXELS, &m_unpackSkipPixels);
  gl.GetIntegerv(GL_UNPACK_SKIP_ROWS, &m_unpackSkipRows);
  gl.GetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &m_pixelUnpackBuffer);
  gl.GetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &m_pixelPackBuffer);
  gl.GetBooleanv(GL_DEPTH_WRITEMASK, &m_depthMask);
  gl.GetBooleanv(GL_COLOR_WRITEMASK, m_colorMask);
  gl.GetFloatv(GL_COLOR_CLEAR_VALUE, m_clearColor);
  gl.GetDoublev(GL_DEPTH_CLEAR_VALUE, &m_clearDepth);
  m_depthTest = gl.IsEnabled(GL_DEPTH_TEST);
  m_cullFace = gl.IsEnabled(GL_CULL_FACE);
  m_blend = gl.IsEnabled(GL_BLEND);
  for (std::size_t i = 0; i < kBlendState.size(); ++i)
    gl.GetIntegerv(kBlendState[i], &m_blendState[i]);
  m_scissorTest = gl.IsEnabled(GL_SCISSOR_TEST);
  m_srgb = gl.IsEnabled(GL_FRAMEBUFFER_SRGB);
  m_multisample = gl.IsEnabled(GL_MULTISAMPLE);
  // The baseline of the renderer's passes (see the class comment).
  for (std::size_t i = 0; i < kDisabledCaps.size(); ++i) {
    m_disabledCaps[i] = gl.IsEnabled(kDisabledCaps[i]);
    if (m_disabledCaps[i]) gl.Disable(kDisabledCaps[i]);
  }
  gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // Uploads and allocations (glTexImage* with nullptr) read client memory, never a host's buffer.
  gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  gl.PixelStorei(GL_UNPACK_SKIP_ROWS, 0);
}

StateGuard::~StateGuard() {
  const gl::GlApi& gl = m_gl;
  auto name = [](GLint v) { return static_cast<GLuint>(v); };
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, name(m_drawFramebuffer));
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, name(m_readFramebuffer));
  gl.BindRenderbuffer(GL_RENDERBUFFER, name(m_renderbuffer));
  gl.Viewport(m_viewport[0], m_viewport[1], m_viewport[2], m_viewport[3]);
  gl.Scissor(m_scissorBox[0], m_scissorBox[1], m_scissorBox[2], m_scissorBox[3]);
  gl.UseProgram(name(m_program));
  gl.BindVertexArray(name(m_vertexArray));
  gl.BindBuffer(GL_ARRAY_BUFFER, name(m_arrayBuffer));
  for (int unit = 0; unit < kUnits; ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    gl.BindTexture(GL_TEXTURE_2D, name(m_texture2d[unit]));
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, name(m_texture2dArray[unit]));
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, name(m_texture2dMultisample[unit]));
    if (m_sampler[unit] != 0) gl.BindSampler(static_cast<GLuint>(unit), name(m_sampler[unit]));
  }
  gl.ActiveTexture(static_cast<GLenum>(m_activeTexture));
  gl.DepthFunc(static_cast<GLenum>(m_depthFunc));
  gl.CullFace(static_cast<GLenum>(m_cullMode));
  gl.FrontFace(static_cast<GLenum>(m_frontFace));
  // Core profiles keep one mode for both faces (glPolygonMode takes GL_FRONT_AND_BACK only).
  gl.PolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(m_polygonMode[0]));
  gl.PixelStorei(GL_PACK_ALIGNMENT, m_packAlignment);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, m_unpackAlignment);
  gl.PixelStorei(GL_UNPACK_ROW_LENGTH, m_unpackRowLength);
  gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, m_unpackSkipPixels);
  gl.PixelStorei(GL_UNPACK_SKIP_ROWS, m_unpackSkipRows);
  gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, name(m_pixelUnpackBuffer));
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, name(m_pixelPackBuffer));
  gl.DepthMask(m_depthMask);
  gl.ColorMask(m_colorMask[0], m_colorMask[1], m_colorMask[2], m_colorMask[3]);
  gl.ClearColor(m_clearColor[0], m_clearColor[1], m_clearColor[2], m_clearColor[3]);
  gl.ClearDepth(m_clearDepth);
  setEnabled(gl, GL_DEPTH_TEST, m_depthTest);
  setEnabled(gl, GL_CULL_FACE, m_cullFace);
  setEnabled(gl, GL_BLEND, m_blend);
  auto e = [&](std::size_t i) { return static_cast<GLenum>(m_blendState[i]); };
  gl.BlendFuncSeparate(e(0), e(1), e(2), e(3));
  gl.BlendEquationSeparate(e(4), e(5));
  setEnabled(gl, GL_SCISSOR_TEST, m_scissorTest);
  setEnabled(gl, GL_FRAMEBUFFER_SRGB, m_srgb);
  setEnabled(gl, GL_MULTISAMPLE, m_multisample);
  for (std::size_t i = 0; i < kDisabledCaps.size(); ++i)
    if (m_disabledCaps[i]) gl.Enable(kDisabledCaps[i]);
}

}  // namespace tissue::render
