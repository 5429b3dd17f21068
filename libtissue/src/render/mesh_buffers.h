#pragma once
// The mesh on the GPU: one buffer per attribute so a deformation re-uploads only what changed
// (glBufferSubData of the changed attributes and vertex range), never UVs or indices. Keeps a
// CPU-side bounding box (mm) for the shadow frusta.
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

/// Vertex attribute locations shared by every surface shader (shaders/common/surface.vert).
enum AttributeLocation : GLuint { kPosition = 0, kNormal = 1, kTangent = 2, kUv = 3, kPlane = 4 };

class MeshBuffers {
 public:
  /// Uploads everything (allocating storage); binds and leaves bound its VAO and buffers.
  Result<void> upload(const gl::GlApi& gl, const MeshArrays& mesh);
  /// Re-uploads the given attributes for the given vertex range in place.
  Result<void> update(const gl::GlApi& gl, const MeshUpdate& update);
  bool empty() const { return m_indexCount == 0; }
  bool hasPlanes() const { return static_cast<bool>(m_planes); }
  GLuint vertexArray() const { return m_vertexArray.id(); }
  GLsizei indexCount() const { return m_indexCount; }
  std::size_t vertexCount() const { return m_vertexCount; }
  /// Axis-aligned bounds of every position uploaded so far (mm; grows, never shrinks).
  Float3 lo() const { return m_lo; }
  Float3 hi() const { return m_hi; }
  /// sqrt(UV area / surface area) of the uploaded shape, UV units per mm (texture-space methods).
  float uvDensity() const { return m_uvDensity; }

 private:
  void grow(std::span<const Float3> positions);
  gl::VertexArray m_vertexArray;
  gl::Buffer m_positions, m_normals, m_tangents, m_uvs, m_planes, m_indices;
  std::size_t m_vertexCount = 0;
  GLsizei m_indexCount = 0;
  Float3 m_lo{}, m_hi{};
  float m_uvDensity = 0.0f;
};

}  // namespace tissue::render
