#include "textures.h"

#include <string>

namespace tissue::render {
namespace {

// Grey, grey+alpha and RGB become RGBA so one upload path fits every image.
Image8 toRgba(const Image8& image) {
  if (image.channels == 4) return image;
  Image8 out(image.width, image.height, 4);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* s = image.at(x, y);
      std::uint8_t* d = out.at(x, y);
      const bool grey = image.channels < 3;
      d[0] = s[0];
      d[1] = grey ? s[0] : s[1];
      d[2] = grey ? s[0] : s[2];
      d[3] = image.channels == 2 ? s[1] : 255;
    }
  }
  return out;
}

}  // namespace

Result<void> uploadTexture(const gl::GlApi& gl, gl::Texture& texture, const Image8& image,
                           TextureEncoding encoding) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * image.channels) {
    return Error{"renderer: texture image is empty or malformed (" + std::to_string(image.width) + "x" +
                 std::to_string(image.height) + ", " + std::to_string(image.channels) + " channels)"};
  }
  const Image8 rgba = toRgba(image);
  if (!texture) texture = gl::Texture::create(gl);
  gl.BindTexture(GL_TEXTURE_2D, texture.id());
  gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  // Image rows run top to bottom and GL's t axis bottom to top: uploading row 0 first puts the
  // image's top at v = 0, so flip v here to keep OBJ's convention (v = 0 at the bottom).
  Image8 flipped = rgba;
  flipVertically(flipped);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.width, rgba.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                flipped.pixels.data());
  if (encoding == TextureEncoding::LinearData) {
    // Data as the CPU models read it: bilinear between texel centres, clamped at the edges.
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return gl::checkGlError(gl, "renderer: data texture upload");
  }
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  return gl::checkGlError(gl, "renderer: texture upload");
}

Result<void> uploadSolidTexture(const gl::GlApi& gl, gl::Texture& texture, std::uint8_t r, std::uint8_t g,
                                std::uint8_t b) {
  Image8 pixel(1, 1, 4);
  pixel.pixels = {r, g, b, 255};
  return uploadTexture(gl, texture, pixel);
}

}  // namespace tissue::render
