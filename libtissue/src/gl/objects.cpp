// Deleting owned GL names; one explicit instantiation per object kind; the census of live names.
#include "tissue/gl/objects.h"

namespace tissue::gl {

template <ObjectKind K>
Object<K> Object<K>::create(const GlApi& gl) {
  GLuint id = 0;
  if constexpr (K == ObjectKind::Buffer) gl.GenBuffers(1, &id);
  if constexpr (K == ObjectKind::VertexArray) gl.GenVertexArrays(1, &id);
  if constexpr (K == ObjectKind::Texture) gl.GenTextures(1, &id);
  if constexpr (K == ObjectKind::Framebuffer) gl.GenFramebuffers(1, &id);
  if constexpr (K == ObjectKind::Renderbuffer) gl.GenRenderbuffers(1, &id);
  if constexpr (K == ObjectKind::Query) gl.GenQueries(1, &id);
  if constexpr (K == ObjectKind::Program) id = gl.CreateProgram();
  return Object(gl, id, true);
}

template <ObjectKind K>
void Object<K>::reset() {
  if (m_owned && m_id != 0 && m_gl) {
    const GlApi& gl = *m_gl;
    if constexpr (K == ObjectKind::Buffer) gl.DeleteBuffers(1, &m_id);
    if constexpr (K == ObjectKind::VertexArray) gl.DeleteVertexArrays(1, &m_id);
    if constexpr (K == ObjectKind::Texture) gl.DeleteTextures(1, &m_id);
    if constexpr (K == ObjectKind::Framebuffer) gl.DeleteFramebuffers(1, &m_id);
    if constexpr (K == ObjectKind::Renderbuffer) gl.DeleteRenderbuffers(1, &m_id);
    if constexpr (K == ObjectKind::Query) gl.DeleteQueries(1, &m_id);
    if constexpr (K == ObjectKind::Program) gl.DeleteProgram(m_id);
  }
  m_gl = nullptr;
  m_id = 0;
  m_owned = false;
}

ObjectCensus countLiveObjects(const GlApi& gl, GLuint maxName) {
  ObjectCensus c;
  for (GLuint id = 1; id <= maxName; ++id) {
    c.buffers += gl.IsBuffer(id) ? 1 : 0;
    c.vertexArrays += gl.IsVertexArray(id) ? 1 : 0;
    c.textures += gl.IsTexture(id) ? 1 : 0;
    c.framebuffers += gl.IsFramebuffer(id) ? 1 : 0;
    c.renderbuffers += gl.IsRenderbuffer(id) ? 1 : 0;
    c.queries += gl.IsQuery(id) ? 1 : 0;
    c.programs += gl.IsProgram(id) ? 1 : 0;
    c.shaders += gl.IsShader(id) ? 1 : 0;
  }
  return c;
}

template class Object<ObjectKind::Buffer>;
template class Object<ObjectKind::VertexArray>;
template class Object<ObjectKind::Texture>;
template class Object<ObjectKind::Framebuffer>;
template class Object<ObjectKind::Renderbuffer>;
template class Object<ObjectKind::Query>;
template class Object<ObjectKind::Program>;

}  // namespace tissue::gl
