#pragma once
/// \file
/// Handles of the GPU resources a renderer holds (Renderer::createMesh, createTexture), shared
/// by the scene (scene.h) and the per-method settings (shading.h).

#include <cstdint>

namespace tissue::render {

/// A mesh uploaded to a renderer (Renderer::createMesh); 0 = none.
struct MeshHandle {
  std::uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
};

/// A texture uploaded to a renderer (Renderer::createTexture); 0 = none (a default is used).
struct TextureHandle {
  std::uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
};

}  // namespace tissue::render
