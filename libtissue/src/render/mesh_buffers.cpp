#include "mesh_buffers.h"

#include <algorithm>
#include <string>

#include "tissue/render/texture_space_math.h"

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
void updateAttribute(const gl::GlApi& gl, const gl::Buffer& buffer, std::size_t first,
                     std::span<const T> data) {
  if (data.empty()) return;
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer.id());
  gl.BufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first * sizeof(T)),
                   static_cast<GLsizeiptr>(data.size_bytes()), data.data());
}

}  // namespace

void MeshBuffers::grow(std::span<const Float3> positions) {
  for (const Float3& p : positions) {
    m_lo = {std::min(m_lo.x, p.x), std::min(m_lo.y, p.y), std::min(m_lo.z, p.z)};
    m_hi = {std::max(m_hi.x, p.x), std::max(m_hi.y, p.y), std::max(m_hi.z, p.z)};
  }
}

Result<void> MeshBuffers::upload(const gl::GlApi& gl, const MeshArrays& mesh) {
  const std::size_t n = mesh.positions.size();
  if (n == 0 || mesh.triangles.empty()) return Error{"renderer: the mesh is empty"};
  if (mesh.normals.size() != n || mesh.tangents.size() != n || mesh.uvs.size() != n ||
      (!mesh.planes.empty() && mesh.planes.size() != n)) {
    return Error{"renderer: mesh arrays differ in length (" + std::to_string(n) + " positions, " +
                 std::to_string(mesh.normals.size()) + " normals, " + std::to_string(mesh.tangents.size()) +
                 " tangents, " + std::to_string(mesh.uvs.size()) + " uvs, " +
                 std::to_string(mesh.planes.size()) +
                 " planes); all need one entry per vertex (planes may be empty)"};
  }
  for (const Triangle& t : mesh.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n)
      return Error{"renderer: a triangle indexes past the vertex arrays"};
  }
  if (!m_vertexArray) m_vertexArray = gl::VertexArray::create(gl);
  gl.BindVertexArray(m_vertexArray.id());
  uploadAttribute(gl, m_positions, mesh.positions, kPosition, 3);
  uploadAttribute(gl, m_normals, mesh.normals, kNormal, 3);
  uploadAttribute(gl, m_tangents, mesh.tangents, kTangent, 4);
  uploadAttribute(gl, m_uvs, mesh.uvs, kUv, 2);
  if (!mesh.planes.empty()) {
    uploadAttribute(gl, m_planes, mesh.planes, kPlane, 4);
  } else {
    m_planes.reset();
    gl.DisableVertexAttribArray(kPlane);
  }
  if (!m_indices) m_indices = gl::Buffer::create(gl);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.triangles.size_bytes()),
                mesh.triangles.data(), GL_STATIC_DRAW);
  m_vertexCount = n;
  m_indexCount = static_cast<GLsizei>(mesh.triangles.size() * 3);
  m_lo = m_hi = mesh.positions[0];
  grow(mesh.positions);
  m_uvDensity = render::uvDensity(mesh.positions, mesh.uvs, mesh.triangles);
  return gl::checkGlError(gl, "renderer: mesh upload");
}

Result<void> MeshBuffers::update(const gl::GlApi& gl, const MeshUpdate& u) {
  if (empty()) return Error{"renderer: updateMesh before the mesh was uploaded"};
  for (const std::size_t size : {u.positions.size(), u.normals.size(), u.tangents.size(), u.planes.size()}) {
    if (size != 0 && u.firstVertex + size > m_vertexCount) {
      return Error{"renderer: updateMesh of vertices " + std::to_string(u.firstVertex) + ".." +
                   std::to_string(u.firstVertex + size) + " runs past the mesh's " +
                   std::to_string(m_vertexCount) + " vertices (the count it was created with)"};
    }
  }
  if (!u.planes.empty() && !hasPlanes()) {
    return Error{"renderer: updateMesh with planes, but the mesh was created without them"};
  }
  updateAttribute(gl, m_positions, u.firstVertex, u.positions);
  updateAttribute(gl, m_normals, u.firstVertex, u.normals);
  updateAttribute(gl, m_tangents, u.firstVertex, u.tangents);
  updateAttribute(gl, m_planes, u.firstVertex, u.planes);
  grow(u.positions);
  return gl::checkGlError(gl, "renderer: mesh update");
}

}  // namespace tissue::render
