#include "mesh_buffers.h"

#include <string>

namespace tissue::render {
namespace {

template <class T>
void uploadAttribute(const gl::GlApi& gl, gl::Buffer& buffer, std::span<const T> data, GLuint location,
                     GLint components) {
  if (!buffer) buffer = gl::Buffer::create(gl);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size_bytes()), data.data(), GL_DYNAMIC_DRAW);
  gl.EnableVertexAttribArray(location);
  gl.VertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(T), nullptr);
}

template <class T>
void updateAttribute(const gl::GlApi& gl, const gl::Buffer& buffer, std::span<const T> data) {
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
  gl.BufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(data.size_bytes()), data.data());
}

}  // namespace

Result<void> MeshBuffers::upload(const gl::GlApi& gl, const MeshArrays& mesh) {
  const std::size_t n = mesh.positions.size();
  if (n == 0 || mesh.triangles.empty()) return Error{"renderer: the mesh is empty"};
  if (mesh.normals.size() != n || mesh.tangents.size() != n || mesh.uvs.size() != n) {
    return Error{"renderer: mesh arrays differ in length (" + std::to_string(n) + " positions, " +
                 std::to_string(mesh.normals.size()) + " normals, " + std::to_string(mesh.tangents.size()) +
                 " tangents, " + std::to_string(mesh.uvs.size()) + " uvs); all need one entry per vertex"};
  }
  for (const Triangle& t : mesh.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n)
      return Error{"renderer: a triangle indexes past the vertex arrays"};
  }
  if (!m_vertexArray) m_vertexArray = gl::VertexArray::create(gl);
  gl.BindVertexArray(m_vertexArray.id());
  uploadAttribute(gl, m_positions, mesh.positions, 0, 3);
  uploadAttribute(gl, m_normals, mesh.normals, 1, 3);
  uploadAttribute(gl, m_tangents, mesh.tangents, 2, 4);
  uploadAttribute(gl, m_uvs, mesh.uvs, 3, 2);
  if (!m_indices) m_indices = gl::Buffer::create(gl);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.triangles.size_bytes()),
                mesh.triangles.data(), GL_STATIC_DRAW);
  m_vertexCount = n;
  m_indexCount = static_cast<GLsizei>(mesh.triangles.size() * 3);
  return gl::checkGlError(gl, "renderer: mesh upload");
}

Result<void> MeshBuffers::update(const gl::GlApi& gl, std::span<const Float3> positions,
                                 std::span<const Float3> normals, std::span<const Float4> tangents) {
  if (empty()) return Error{"renderer: updateMesh before setMesh"};
  if (positions.size() != m_vertexCount || normals.size() != m_vertexCount ||
      tangents.size() != m_vertexCount) {
    return Error{"renderer: updateMesh needs " + std::to_string(m_vertexCount) +
                 " positions, normals and tangents (the count given to setMesh)"};
  }
  updateAttribute(gl, m_positions, positions);
  updateAttribute(gl, m_normals, normals);
  updateAttribute(gl, m_tangents, tangents);
  return gl::checkGlError(gl, "renderer: mesh update");
}

}  // namespace tissue::render
