#pragma once
// Textures from Image8: expanded to RGBA8; colour mipmapped and repeating, data clamped.
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/gl/objects.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

/// Uploads `image` (1-4 channels) into `texture` (created when empty) on the active unit,
/// sampled as `encoding` says (renderer.h).
Result<void> uploadTexture(const gl::GlApi& gl, gl::Texture& texture, const Image8& image,
                           TextureEncoding encoding = TextureEncoding::Srgb);

/// A 1x1 texture of one RGBA colour.
Result<void> uploadSolidTexture(const gl::GlApi& gl, gl::Texture& texture, std::uint8_t r, std::uint8_t g,
                                std::uint8_t b);

}  // namespace tissue::render
