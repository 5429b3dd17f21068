#pragma once
// The mesh on the GPU: one buffer per attribute so a deformation re-uploads only positions,
// normals and tangents (glBufferSubData), never UVs or indices.
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

class MeshBuffers {
 public:
  /// Uploads everything (allocating storage); binds and leaves bound its VAO and buffers.
  Result<void> upload(const gl::GlApi& gl, const MeshArrays& mesh);
  /// Re-uploads the deforming attributes in place.
  Result<void> update(const gl::GlApi& gl, std::span<const Float3> positions, std::span<const Float3> normals,
                      std::span<const Float4> tangents);
  bool empty() const { return m_indexCount == 0; }
  GLuint vertexArray() const { return m_vertexArray.id(); }
  GLsizei indexCount() const { return m_indexCount; }

 private:
  gl::VertexArray m_vertexArray;
  gl::Buffer m_positions, m_normals, m_tangents, m_uvs, m_indices;
  std::size_t m_vertexCount = 0;
  GLsizei m_indexCount = 0;
};

}  // namespace tissue::render
